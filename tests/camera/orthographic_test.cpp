#include <gtest/gtest.h>

#include "camera/camera_test_util.hpp"

namespace glint {
namespace {

TEST(Orthographic, RaysAreParallelAndTheViewIsHeightTall) {
    // Looking down −x from (5, 1, 2) with a view 4 units tall on a 200 × 100 image: 0.04 units a pixel.
    const Scene scene =
        test::camera_scene("{type: orthographic, eye: [5, 1, 2], look_at: [0, 1, 2], height: 4}");
    const Ray centre = scene.view.camera->generate_ray({100, 50}, {0.3, 0.7});
    EXPECT_EQ(centre.origin, Vec3(5, 1, 2));
    EXPECT_LT(length(centre.direction - Vec3(-1, 0, 0)), 1e-15);
    // With up = +y and w = +x, u = up × w = −z: the right of the image is −z.
    const Ray top_right = scene.view.camera->generate_ray({200, 0}, {});
    EXPECT_LT(length(top_right.origin - Vec3(5, 3, -2)), 1e-12);
    EXPECT_EQ(top_right.direction, centre.direction);
    // A world point lands on the pixel computed by hand: (x, y, z) = (−3, 1.6, 2.8) is 0.6 up and 0.8
    // left of the axis, so at pixel (100 − 0.8/0.04, 50 − 0.6/0.04) = (80, 35), at any depth.
    const Ray r = scene.view.camera->generate_ray({80, 35}, {});
    EXPECT_LT(test::distance_to_line(r, {-3, 1.6, 2.8}), 1e-12);
}

TEST(Orthographic, LooksStraightDownWithTheDefaultUp) {
    const Scene scene = test::camera_scene("{type: orthographic, eye: [0, 10, 0], look_at: [0, 0, 0]}");
    const Ray r = scene.view.camera->generate_ray({0, 0}, {});
    EXPECT_TRUE(is_finite(r.origin));
    EXPECT_LT(length(r.direction - Vec3(0, -1, 0)), 1e-15);
    // The top of the image is −z (the degenerate-up rule), the default height 2 gives 1 unit above.
    EXPECT_LT(length(r.origin - Vec3(-2, 10, -1)), 1e-12);
}

}  // namespace
}  // namespace glint
