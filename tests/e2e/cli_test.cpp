// The command line as a user meets it: the default scene, every example, help and version.
#include <gtest/gtest.h>

#include <cstdio>

#include "glint/image/image_io.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

TEST(Cli, RendersTheDefaultSceneToPngWithASummary) {
    test::TempDir dir;
    const auto out = dir / "default.png";
    const auto r = test::run_glint("render --width 64 --height 36 --spp 2 -o '" + out.string() + "'");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_GT(std::filesystem::file_size(out), 100u);
    // The summary: resolution, samples per pixel, time, rays, Mrays/s.
    EXPECT_NE(r.output.find("64x36, 4 spp"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("Mrays/s"), std::string::npos) << r.output;
    // No progress bar when stderr is not a terminal.
    EXPECT_EQ(r.output.find("ETA"), std::string::npos) << r.output;
}

// The rays by kind in the summary of a render of the default scene at 250 × 100 pixels, 4 spp, with
// `integrator`: "N M rays (C M camera, B M bounces, S M shadow)".
struct RaysInSummary {
    double total = -1, camera = -1, bounces = -1, shadow = -1;
};
RaysInSummary rays_of_render(const std::string& integrator) {
    test::TempDir dir;
    const auto r = test::run_glint("render --width 250 --height 100 --spp 4 --integrator " + integrator +
                                   " -o '" + (dir / "a.pfm").string() + "'");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    RaysInSummary rays;
    const std::size_t at = r.output.rfind(" M rays (");
    const std::size_t start = at == std::string::npos ? at : r.output.rfind(", ", at);
    if (start == std::string::npos ||
        std::sscanf(r.output.c_str() + start + 2, "%lf M rays (%lf M camera, %lf M bounces, %lf M shadow)",
                    &rays.total, &rays.camera, &rays.bounces, &rays.shadow) != 4) {
        ADD_FAILURE() << "no rays by kind in: " << r.output;
    }
    return rays;
}

TEST(Cli, TheSummaryCountsEachKindOfRay) {
    // One camera ray a sample: 250 × 100 pixels × 4 samples = 0.10 M.
    const RaysInSummary path = rays_of_render("path");
    EXPECT_EQ(path.camera, 0.10);
    EXPECT_GT(path.bounces, 0);
    EXPECT_GT(path.shadow, 0);
    EXPECT_NEAR(path.camera + path.bounces + path.shadow, path.total, 0.015);  // each rounded to 0.01
    // The paper's ray casting traces camera and shadow rays, and no bounce.
    const RaysInSummary cast = rays_of_render("raycast");
    EXPECT_EQ(cast.camera, 0.10);
    EXPECT_EQ(cast.bounces, 0.0);
}

TEST(Cli, WritesExrAndPfmAndRejectsUnknownExtensions) {
    test::TempDir dir;
    for (const std::string name : {"a.exr", "a.pfm"}) {
        const auto r = test::run_glint("render --width 16 --height 9 --spp 1 --quiet -o '" +
                                       (dir / name).string() + "'");
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_TRUE(std::filesystem::exists(dir / name));
    }
    const auto r = test::run_glint("render --quiet -o '" + (dir / "a.bmp").string() + "'");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find(".png, .pfm, .exr"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "a.bmp"));
}

TEST(Cli, BadFlagsAreBadInput) {
    EXPECT_EQ(test::run_glint("render --spp 0 --quiet -o /tmp/never.png").exit_code, 2);
    EXPECT_EQ(test::run_glint("render --frobnicate").exit_code, 2);
    const auto r = test::run_glint("render --sampler jitterd --quiet -o /tmp/never.png");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("did you mean 'jittered'"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists("/tmp/never.png"));
    EXPECT_EQ(test::run_glint("render -o /nonexistent-dir/x.png --quiet").exit_code, 2);
}

TEST(Cli, HelpAndVersion) {
    const auto help = test::run_glint("--help");
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.output.find("render"), std::string::npos);
    const auto version = test::run_glint("--version");
    EXPECT_EQ(version.exit_code, 0);
    EXPECT_NE(version.output.find(GLINT_VERSION), std::string::npos);
    const auto render_help = test::run_glint("render --help");
    EXPECT_EQ(render_help.exit_code, 0);
    EXPECT_NE(render_help.output.find("--spp"), std::string::npos);
}

TEST(Cli, EveryExampleRenders) {
    test::TempDir dir;
    int rendered = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(GLINT_SOURCE_DIR) + "/examples")) {
        const auto ext = entry.path().extension();
        if (ext != ".yaml" && ext != ".json") {
            continue;
        }
        const auto out = dir / (entry.path().stem().string() + ".png");
        const auto r = test::run_glint("render '" + entry.path().string() +
                                       "' --width 32 --height 24 --spp 1 --quiet -o '" + out.string() + "'");
        EXPECT_EQ(r.exit_code, 0) << entry.path() << "\n" << r.output;
        EXPECT_TRUE(std::filesystem::exists(out)) << entry.path();
        ++rendered;
    }
    EXPECT_GE(rendered, 1);
}

}  // namespace
}  // namespace glint
