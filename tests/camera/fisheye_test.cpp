#include <gtest/gtest.h>

#include "camera/camera_test_util.hpp"
#include "glint/core/math.hpp"
#include "glint/params/diagnostics.hpp"

namespace glint {
namespace {

TEST(Fisheye, AngleFromTheAxisGrowsLinearlyWithRadius) {
    // 200 × 100 image: the image circle is 100 pixels across, centred at (100, 50).
    const Scene scene = test::camera_scene("{type: fisheye, eye: [0, 0, 0], look_at: [0, 0, -1]}");
    const auto dir = [&](double x, double y) {
        return scene.view.camera->generate_ray({x, y}, {}).direction;
    };
    EXPECT_LT(length(dir(100, 50) - Vec3(0, 0, -1)), 1e-15);
    // 180° across the circle: its top is straight up, its right edge straight right.
    EXPECT_LT(length(dir(100, 0) - Vec3(0, 1, 0)), 1e-15);
    EXPECT_LT(length(dir(150, 50) - Vec3(1, 0, 0)), 1e-15);
    // Equidistant: 20 pixels from the centre (of 50) is 0.4 · 90° = 36° off the axis, in the direction
    // of the film offset (down-left here).
    const Vec3 d = dir(100 - 12, 50 + 16);
    EXPECT_NEAR(length(d), 1, 1e-15);
    EXPECT_NEAR(std::acos(-d.z), radians(36), 1e-12);
    EXPECT_NEAR(std::atan2(d.y, d.x), std::atan2(-16.0, -12.0), 1e-12);
}

TEST(Fisheye, ThreeSixtyDegreesSeesBehindAtTheRim) {
    const Scene scene =
        test::camera_scene("{type: fisheye, eye: [0, 0, 0], look_at: [0, 0, -1], fov: 360}", 100, 100);
    EXPECT_LT(length(scene.view.camera->generate_ray({50, 25}, {}).direction - Vec3(0, 1, 0)), 1e-15);
    EXPECT_LT(length(scene.view.camera->generate_ray({100, 50}, {}).direction - Vec3(0, 0, 1)), 1e-15);
}

TEST(Fisheye, OutsideTheImageCircleSeesNothingAndRendersBlack) {
    const Scene scene = test::camera_scene("{type: fisheye, eye: [0, 0, 0], look_at: [0, 0, -1], fov: 120}");
    EXPECT_FALSE(sees_scene(scene.view.camera->generate_ray({10, 50}, {})));  // left of the circle
    EXPECT_FALSE(
        sees_scene(scene.view.camera->generate_ray({140, 90}, {})));  // a corner of the circle's square
    EXPECT_TRUE(sees_scene(scene.view.camera->generate_ray({140, 70}, {})));
    // Rendered against a white background: black outside the circle, white inside, no NaN.
    const Scene lit = test::scene_from_text(
        "render: {width: 40, height: 20, samples: 4}\n"
        "camera: {type: fisheye, eye: [0, 0, 0], look_at: [0, 0, -1]}\nbackground: 1\n");
    RenderStats stats;
    const Film film = test::render_film(lit, &stats);
    EXPECT_EQ(stats.nonfinite_samples, 0u);
    EXPECT_EQ(film.pixel(2, 10), Rgb(0));
    EXPECT_EQ(film.pixel(20, 10), Rgb(1));
    EXPECT_EQ(film.pixel(38, 2), Rgb(0));
}

TEST(Fisheye, RejectsAFieldOfViewOutsideZeroTo360) {
    EXPECT_THROW(test::camera_scene("{type: fisheye, fov: 0}"), SceneError);
    EXPECT_THROW(test::camera_scene("{type: fisheye, fov: 400}"), SceneError);
}

}  // namespace
}  // namespace glint
