// How a positioned message quotes its line: the part of SourceFile a message reads, and the window of a
// long line around the column.
#include "glint/params/diagnostics.hpp"

#include <gtest/gtest.h>

#include <string>

namespace glint {
namespace {

TEST(SourceFileLine, APartOfALineFromAByteOnIsCutAtTheLineEnd) {
    const auto file = SourceFile::from_text("f.txt", "first\nsecond line\r\nthird");
    EXPECT_EQ(file->line(2).value(), "second line");
    EXPECT_EQ(file->line(2, 7).value(), "line");
    EXPECT_EQ(file->line(2, 7, 2).value(), "li");
    EXPECT_EQ(file->line(2, 50).value(), "");  // past the line's end: nothing of it
    EXPECT_EQ(file->line(3, 1, 100).value(), "hird");
    EXPECT_FALSE(file->line(4).has_value());
}

// The last line of a message: where the caret is, as an index into the quoted line above it.
std::size_t caret_index(const std::string& report) {
    return report.size() - report.rfind('\n') - 2;
}
std::string quoted_line(const std::string& report) {
    const std::string before_caret = report.substr(0, report.rfind('\n'));
    return before_caret.substr(before_caret.rfind('\n') + 1);
}

TEST(FormatDiagnostic, FarAlongALongLineOnlyAWindowIsQuotedWithTheCaretOnTheColumn) {
    std::string line(100000, 'a');
    line[77777] = 'X';
    const auto file = SourceFile::from_text("long.json", line + "\nnext\n");
    const std::string report = format_diagnostic({file, 1, 77778}, "here");
    EXPECT_LT(report.size(), 300u) << report;
    const std::string quoted = quoted_line(report);
    ASSERT_LT(caret_index(report), quoted.size()) << report;
    EXPECT_EQ(quoted[caret_index(report)], 'X') << report;
}

TEST(FormatDiagnostic, AColumnPastTheEndOfALongLineIsKeptJustAfterIt) {
    const std::string line = std::string(299, 'b') + "E";
    const auto file = SourceFile::from_text("long.json", line + "\n" + std::string(1000, 'n') + "\n");
    const std::string report = format_diagnostic({file, 1, 5000}, "past the end");
    const std::string quoted = quoted_line(report);
    // The window ends with the line's last character and "...", the caret just after that character:
    // nothing of the next line is quoted.
    EXPECT_EQ(quoted.find('n'), std::string::npos) << report;
    ASSERT_GE(caret_index(report), 1u);
    EXPECT_EQ(quoted[caret_index(report) - 1], 'E') << report;
}

}  // namespace
}  // namespace glint
