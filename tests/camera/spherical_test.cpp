#include <gtest/gtest.h>

#include "camera/camera_test_util.hpp"
#include "glint/core/math.hpp"

namespace glint {
namespace {

TEST(Spherical, LongitudeAndLatitudeSpanTheImage) {
    // A 360 × 180 panorama: one degree a pixel. Looking down −z with up +y (u = +x, v = +y, w = +z).
    for (const std::string type : {"spherical", "equirectangular"}) {
        const Scene scene =
            test::camera_scene("{type: " + type + ", eye: [1, 2, 3], look_at: [1, 2, 0]}", 360, 180);
        const auto dir = [&](double x, double y) {
            return scene.view.camera->generate_ray({x, y}, {}).direction;
        };
        EXPECT_EQ(scene.view.camera->generate_ray({10, 10}, {}).origin, Vec3(1, 2, 3));
        EXPECT_LT(length(dir(180, 90) - Vec3(0, 0, -1)), 1e-15);  // the centre looks at look_at
        EXPECT_LT(length(dir(270, 90) - Vec3(1, 0, 0)), 1e-15);   // 90° right
        EXPECT_LT(length(dir(90, 90) - Vec3(-1, 0, 0)), 1e-15);   // 90° left
        EXPECT_LT(length(dir(0, 90) - Vec3(0, 0, 1)), 1e-15);     // behind, at the left edge …
        EXPECT_LT(length(dir(360, 90) - Vec3(0, 0, 1)), 1e-15);   // … and at the right edge
        EXPECT_LT(length(dir(123, 0) - Vec3(0, 1, 0)), 1e-15);    // the top row is the zenith
        EXPECT_LT(length(dir(17, 180) - Vec3(0, -1, 0)), 1e-15);  // the bottom row the nadir
        // 30° right and 45° up.
        const Vec3 d = dir(210, 45);
        EXPECT_NEAR(length(d), 1, 1e-15);
        EXPECT_NEAR(d.y, std::sin(radians(45)), 1e-15);
        EXPECT_NEAR(std::atan2(d.x, -d.z), radians(30), 1e-14);
    }
}

}  // namespace
}  // namespace glint
