// The image is a pure function of scene and seed: the same bits for any thread count or tiling.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "test_util.hpp"

namespace glint {
namespace {

std::string read_bytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

TEST(Determinism, PfmIsBitIdenticalWithOneAndTwoThreads) {
    test::TempDir dir;
    const auto one = dir / "one.pfm";
    const auto two = dir / "two.pfm";
    const std::string common = "render --width 96 --height 54 --spp 4 --seed 3 --quiet ";
    ASSERT_EQ(test::run_glint(common + "--threads 1 -o '" + one.string() + "'").exit_code, 0);
    ASSERT_EQ(test::run_glint(common + "--threads 2 -o '" + two.string() + "'").exit_code, 0);
    const std::string a = read_bytes(one);
    ASSERT_GT(a.size(), 96u * 54 * 12);
    EXPECT_TRUE(a == read_bytes(two));
}

TEST(Determinism, TileSizeDoesNotChangeTheImage) {
    RenderFlags overrides;
    overrides.width = 50;
    overrides.height = 30;
    overrides.samples_per_pixel = 5;
    Scene a = build_scene(default_scene(), overrides);
    a.view.settings.tile_size = 16;
    Scene b = build_scene(default_scene(), overrides);
    b.view.settings.tile_size = 7;
    const Film fa = test::render_film(a);
    const Film fb = test::render_film(b);
    for (int y = 0; y < 30; ++y) {
        for (int x = 0; x < 50; ++x) {
            ASSERT_EQ(fa.pixel(x, y), fb.pixel(x, y)) << x << "," << y;
        }
    }
}

TEST(Determinism, TheSeedChangesTheNoiseButNotTheMean) {
    RenderFlags overrides;
    overrides.width = 40;
    overrides.height = 24;
    overrides.samples_per_pixel = 4;
    overrides.sampler = "random";
    overrides.seed = 1;
    const Film a = test::render_film(build_scene(default_scene(), overrides));
    overrides.seed = 2;
    const Film b = test::render_film(build_scene(default_scene(), overrides));
    int differing = 0;
    double mean_a = 0, mean_b = 0;
    for (int y = 0; y < 24; ++y) {
        for (int x = 0; x < 40; ++x) {
            differing += a.pixel(x, y) != b.pixel(x, y);
            mean_a += a.pixel(x, y).luminance();
            mean_b += b.pixel(x, y).luminance();
        }
    }
    EXPECT_GT(differing, 100);
    EXPECT_NEAR(mean_a / mean_b, 1.0, 0.02);
}

}  // namespace
}  // namespace glint
