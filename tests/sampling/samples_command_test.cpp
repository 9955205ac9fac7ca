// `glint samples` end to end: it writes a PNG and a CSV, its points are the library's, and bad
// arguments exit with 2.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "glint/sampling/pattern_stats.hpp"
#include "glint/sampling/sampler.hpp"

namespace glint {
namespace {

int exit_code_of(const std::string& arguments) {
    const std::string command = std::string(GLINT_CLI_PATH) + " samples " + arguments + " >/dev/null 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string output_of(const std::string& arguments) {
    const std::string command = std::string(GLINT_CLI_PATH) + " samples " + arguments + " 2>/dev/null";
    FILE* pipe = popen(command.c_str(), "r");
    std::string text;
    char buffer[4096];
    while (pipe != nullptr && std::fgets(buffer, sizeof(buffer), pipe) != nullptr) {
        text += buffer;
    }
    if (pipe != nullptr) {
        pclose(pipe);
    }
    return text;
}

std::filesystem::path temporary(const std::string& name) {
    return std::filesystem::temp_directory_path() /
           ("glint_samples_test_" + std::to_string(::getpid()) + name);
}

TEST(SamplesCommand, WritesAPngPlot) {
    const auto png = temporary(".png");
    ASSERT_EQ(exit_code_of("--pattern multi-jittered --count 16 --pixel 2,3 -o " + png.string()), 0);
    std::ifstream in(png, std::ios::binary);
    char signature[8] = {};
    in.read(signature, 8);
    EXPECT_EQ(std::string(signature + 1, 3), "PNG");
    EXPECT_GT(std::filesystem::file_size(png), 1000u);
    std::filesystem::remove(png);
    const auto warped = temporary("_warp.png");
    EXPECT_EQ(exit_code_of("--pattern sobol --count 64 --warp hemisphere:2 -o " + warped.string()), 0);
    EXPECT_TRUE(std::filesystem::exists(warped));
    std::filesystem::remove(warped);
}

TEST(SamplesCommand, CsvHoldsTheLibrarysPoints) {
    const auto csv = temporary(".csv");
    ASSERT_EQ(exit_code_of("--pattern hammersley --count 8 --pixel 4,1 --seed 9 -o " + csv.string()), 0);
    std::ifstream in(csv);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header, "x,y");
    const auto sampler = make_sampler("hammersley", 8);
    const std::vector<Point2> expected = pattern_points(*sampler, SampleKey{9, 4, 1, 0});
    std::string line;
    size_t i = 0;
    for (; std::getline(in, line); ++i) {
        ASSERT_LT(i, expected.size());
        double x = 0, y = 0;
        char comma = 0;
        std::istringstream(line) >> x >> comma >> y;
        EXPECT_DOUBLE_EQ(x, expected[i].x);
        EXPECT_DOUBLE_EQ(y, expected[i].y);
    }
    EXPECT_EQ(i, expected.size());
    std::filesystem::remove(csv);
    // Without -o the same lines go to stdout.
    std::istringstream stdout_text(output_of("--pattern hammersley --count 8 --pixel 4,1 --seed 9"));
    std::getline(stdout_text, header);
    EXPECT_EQ(header, "x,y");
}

TEST(SamplesCommand, StatsReportTheConditions) {
    const std::string stats = output_of("--pattern n-rooks --count 16 --stats");
    EXPECT_NE(stats.find("n-rooks (n x n grid)        yes"), std::string::npos) << stats;
    EXPECT_NE(stats.find("star discrepancy (L2)"), std::string::npos);
    EXPECT_NE(output_of("--pattern jittered --count 16 --stats").find("jittered (4 x 4 cells)     yes"),
              std::string::npos);
}

TEST(SamplesCommand, BadArgumentsExitWithTwo) {
    EXPECT_EQ(exit_code_of(""), 2);                              // no pattern
    EXPECT_EQ(exit_code_of("--pattern no-such-pattern"), 2);     // unknown pattern
    EXPECT_EQ(exit_code_of("--pattern sobol --count 0"), 2);     // out of range
    EXPECT_EQ(exit_code_of("--pattern sobol --count many"), 2);  // not a number
    EXPECT_EQ(exit_code_of("--pattern sobol --pixel 3"), 2);     // not X,Y
    EXPECT_EQ(exit_code_of("--pattern sobol --pixel -1,2"), 2);  // negative
    EXPECT_EQ(exit_code_of("--pattern sobol --warp cube"), 2);   // unknown warp
    EXPECT_EQ(exit_code_of("--pattern sobol --warp hemisphere:-1"), 2);
    EXPECT_EQ(exit_code_of("--pattern sobol -o out.txt"), 2);  // unknown format
    EXPECT_EQ(exit_code_of("--pattern sobol -o /no/such/folder/a.png"), 2);
    EXPECT_EQ(exit_code_of("--convergence -o plot.csv"), 2);  // the plot is a PNG
    EXPECT_EQ(exit_code_of("--pattern sobol --no-such-flag"), 2);
}

}  // namespace
}  // namespace glint
