// RenderCallbacks::time_limit_seconds and `glint render --time-limit`: the render stops at the end of the
// pass that crosses the limit, with every pixel holding the same samples — the image a render of that
// many samples per pixel makes, bit for bit.
#include <gtest/gtest.h>

#include "test_util.hpp"

namespace glint {
namespace {

const char* kScene =
    "render: {width: 24, height: 16, samples: 64, integrator: path, sampler: random}\n"
    "objects:\n  - {type: sphere, center: [0, 0, 0], radius: 1}\n"
    "lights:\n  - {type: environment, radiance: [0.5, 0.7, 1.0]}\n";

TEST(TimeLimit, StopsAfterThePassThatCrossesItWithTheImageOfThatManySamples) {
    const Scene scene = test::scene_from_text(kScene);
    Film limited(24, 16);
    RenderCallbacks callbacks;
    callbacks.time_limit_seconds = 1e-9;  // crossed by the first pass, which takes samples 0 and 1
    const RenderStats stats = render(*scene.world, scene.view, limited, callbacks);
    EXPECT_TRUE(stats.time_limit_reached);
    EXPECT_FALSE(stats.cancelled);
    ASSERT_EQ(stats.samples_per_pixel, 2u);

    RenderFlags two_samples;
    two_samples.samples_per_pixel = 2;
    const Film reference = test::render_film(test::scene_from_text(kScene, two_samples));
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 24; ++x) {
            ASSERT_EQ(limited.pixel(x, y).r, reference.pixel(x, y).r) << x << ", " << y;
            ASSERT_EQ(limited.sample_count(x, y), 2u);
        }
    }
}

TEST(TimeLimit, ARenderWithinItsLimitTakesEverySample) {
    const Scene scene = test::scene_from_text(kScene);
    Film film(24, 16);
    RenderCallbacks callbacks;
    callbacks.time_limit_seconds = 3600;
    const RenderStats stats = render(*scene.world, scene.view, film, callbacks);
    EXPECT_FALSE(stats.time_limit_reached);
    EXPECT_EQ(stats.samples_per_pixel, 64u);
}

TEST(TimeLimit, TheCliWritesTheImageReachedAndSaysSo) {
    test::TempDir dir;
    dir.write("s.yaml", kScene);
    const auto result = test::run_glint("render '" + (dir / "s.yaml").string() + "' -o '" +
                                        (dir / "s.pfm").string() + "' --spp 1000000 --time-limit 0.001 -q");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("time limit of 0.001 s reached"), std::string::npos) << result.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "s.pfm"));
    EXPECT_EQ(test::run_glint("render '" + (dir / "s.yaml").string() + "' --time-limit -1").exit_code, 2);
}

}  // namespace
}  // namespace glint
