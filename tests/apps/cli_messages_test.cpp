// The command line's mistakes get messages as good as the scene file's (issue 15): exit code 2 and a
// message that names the mistake and the fix.
#include <gtest/gtest.h>

#include "test_util.hpp"

namespace glint {
namespace {

void expect_message(const std::string& arguments, const std::string& message) {
    const test::CommandResult result = test::run_glint(arguments);
    EXPECT_EQ(result.exit_code, 2) << arguments << "\n" << result.output;
    EXPECT_NE(result.output.find(message), std::string::npos) << arguments << "\n" << result.output;
}

TEST(CliMessages, MistakesAreNamedWithTheFix) {
    expect_message("rendr", "unknown command 'rendr'; did you mean 'render'?");
    expect_message("", "a command is required: render, samples, serve, info, convert");
    expect_message("render --widht 5", "unknown option '--widht'; did you mean '--width'?");
    expect_message("render --spp abc", "--spp = abc: not a number");
    expect_message("render --seed -1", "render.seed must be zero or more");
}

}  // namespace
}  // namespace glint
