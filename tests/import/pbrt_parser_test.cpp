// The pbrt-v4 tokenizer and statement parser: the syntax, its errors at file:line:col, and its bounds.
#include <gtest/gtest.h>

#include "glint/import/pbrt_parser.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

std::vector<PbrtStatement> parse(const std::string& text, const PbrtLimits& limits = {}) {
    std::vector<PbrtStatement> statements;
    parse_pbrt_text(
        text, "t.pbrt", ".", [&](PbrtStatement& s) { statements.push_back(s); }, limits);
    return statements;
}

// The message and position of the error `text` gives.
std::string error_of(const std::string& text, const PbrtLimits& limits = {}) {
    try {
        parse(text, limits);
    } catch (const SceneError& e) {
        return std::to_string(e.position().line) + ":" + std::to_string(e.position().column) + ": " +
               e.message();
    }
    return "no error";
}

TEST(PbrtParser, ReadsDirectivesArgumentsAndParameters) {
    const auto statements = parse(
        "# a comment\n"
        "LookAt 0 1 2  3 4 5  0 1 0 # another\n"
        "Shape \"sphere\" \"float radius\" 2.5 \"string name\" [ \"a\\\"b\" ]\n"
        "  \"bool flag\" true \"rgb c\" [0.1 .2 +3e-1]\n"
        "Transform [1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1]\n"
        "ActiveTransform EndTime\n");
    ASSERT_EQ(statements.size(), 4u);
    EXPECT_EQ(statements[0].directive, "LookAt");
    EXPECT_EQ(statements[0].numbers, (std::vector<double>{0, 1, 2, 3, 4, 5, 0, 1, 0}));
    EXPECT_EQ(statements[0].pos.line, 2);
    EXPECT_EQ(statements[0].pos.column, 1);
    const PbrtStatement& shape = statements[1];
    EXPECT_EQ(shape.strings, std::vector<std::string>{"sphere"});
    ASSERT_EQ(shape.params.size(), 4u);
    EXPECT_EQ(shape.params[0].type, "float");
    EXPECT_EQ(shape.params[0].name, "radius");
    EXPECT_EQ(shape.params[0].numbers, std::vector<double>{2.5});
    EXPECT_EQ(shape.params[1].strings, std::vector<std::string>{"a\"b"});
    EXPECT_EQ(shape.params[2].booleans, std::vector<bool>{true});
    EXPECT_EQ(shape.params[3].numbers, (std::vector<double>{0.1, 0.2, 0.3}));
    EXPECT_EQ(shape.params[3].pos.line, 4);
    EXPECT_EQ(shape.params[3].pos.column, 20);
    EXPECT_EQ(statements[2].numbers.size(), 16u);
    EXPECT_EQ(statements[3].strings, std::vector<std::string>{"EndTime"});
}

TEST(PbrtParser, MalformedInputIsAnErrorAtItsPosition) {
    EXPECT_EQ(error_of("Shape \"sphere\"\n  Sphere").substr(0, 53),
              "2:3: unknown directive 'Sphere'; did you mean 'Shape'");
    EXPECT_EQ(error_of("Shape \"sphere\" \"float radius\" [1 2"),
              "1:35: the list of 'radius' opened at line 1 is not closed: found the end of the file");
    EXPECT_EQ(error_of("Shape \"sphere\" \"float radius\" \"two\""),
              "1:31: 'radius' is a float parameter: expected a finite number, found the string \"two\"");
    EXPECT_EQ(error_of("Shape \"sphere\" \"floot radius\" 1").substr(0, 37),
              "1:16: unknown parameter type 'floot';");
    EXPECT_EQ(error_of("Shape \"sphere\" \"float\" 1"),
              "1:16: expected a parameter declared as \"type name\", found the string \"float\"");
    EXPECT_EQ(error_of("Shape \"sphere\n"), "1:7: the quoted string is not closed on its line");
    EXPECT_EQ(error_of("Shape \"a\\q\""),
              "1:9: unknown escape '\\q' in a quoted string (known: \\b \\f "
              "\\n \\r \\t \\\\ \\' \\\")");
    EXPECT_EQ(error_of("LookAt 0 1 2 3"), "1:15: LookAt takes 9 numbers, found the end of the file after 4");
    EXPECT_EQ(error_of("Translate 1 nan 2"), "1:13: Translate takes 3 numbers, found 'nan' after 1");
    EXPECT_EQ(error_of("Translate 1 1e999 2"), "1:13: Translate takes 3 numbers, found '1e999' after 1");
    EXPECT_EQ(error_of("\"float x\" 1"),
              "1:1: expected a directive (Shape, LookAt, …), found the string "
              "\"float x\"");
    EXPECT_EQ(error_of("Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 1]"),
              "1:22: 'P' is a point3 parameter: its 5 numbers are not a whole number of values of 3");
    EXPECT_EQ(error_of("Shape \"s\" \"bool b\" yes"),
              "1:20: 'b' is a bool parameter: expected true or false, found 'yes'");
}

TEST(PbrtParser, ListsAreBoundedBeforeTheyGrow) {
    PbrtLimits limits;
    limits.max_list_values = 4;
    EXPECT_NO_THROW(parse("Shape \"s\" \"float x\" [1 2 3 4]", limits));
    EXPECT_EQ(error_of("Shape \"s\" \"float x\" [1 2 3 4 5]", limits).substr(0, 44),
              "1:21: the list of 'x' has more than 4 values");
}

TEST(PbrtParser, IncludesResolveAgainstTheSceneFolderAndAreBounded) {
    test::TempDir dir;
    dir.write("inner.pbrt", "Translate 1 2 3\n");
    std::filesystem::create_directories(dir / "sub");
    // pbrt-v4 resolves every name against the folder of the scene it was given, also from inside an
    // included file.
    dir.write("sub/middle.pbrt", "Include \"inner.pbrt\"\nImport \"inner.pbrt\"\n");
    dir.write("main.pbrt", "Include \"sub/middle.pbrt\"\n");
    std::vector<std::string> directives;
    parse_pbrt_file(dir / "main.pbrt", dir.path(),
                    [&](PbrtStatement& s) { directives.push_back(s.directive); });
    EXPECT_EQ(directives, (std::vector<std::string>{"Translate", "ImportBegin", "Translate", "ImportEnd"}));

    dir.write("loop.pbrt", "Include \"loop.pbrt\"\n");
    try {
        parse_pbrt_file(dir / "loop.pbrt", dir.path(), [](PbrtStatement&) {});
        FAIL() << "a file that includes itself must be refused";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.message(), "Include nested more than 32 deep (a file that includes itself?)");
        EXPECT_EQ(e.position().line, 1);
    }
    // Two includes of itself at each level would be 2^32 files without the count of all files read.
    dir.write("twice.pbrt", "Include \"twice.pbrt\"\nInclude \"twice.pbrt\"\n");
    PbrtLimits limits;
    limits.max_files = 50;
    EXPECT_THROW(parse_pbrt_file(
                     dir / "twice.pbrt", dir.path(), [](PbrtStatement&) {}, limits),
                 SceneError);
    EXPECT_THROW(parse("Include \"missing.pbrt\""), SceneError);
}

}  // namespace
}  // namespace glint
