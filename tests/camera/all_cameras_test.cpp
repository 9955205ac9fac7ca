// Properties every camera in the table must have.
#include <gtest/gtest.h>

#include <vector>

#include "camera/camera_test_util.hpp"

namespace glint {
namespace {

// The extra keys a camera type needs to be built.
std::string required_keys(const std::string& type) {
    return type == "thin-lens" ? ", lens_radius: 0.2" : "";
}

TEST(AllCameras, LookingStraightDownOrUpWithTheDefaultUpGivesFiniteUnitRays) {
    for (const CameraEntry& entry : camera_table()) {
        for (const std::string view :
             {"eye: [0, 5, 0], look_at: [0, 0, 0]", "eye: [1, -2, 3], look_at: [1, 7, 3]",
              "eye: [0, 0, 0], look_at: [0, 0, -1]"}) {
            SCOPED_TRACE(entry.name + " " + view);
            const Scene scene =
                test::camera_scene("{type: " + entry.name + ", " + view + required_keys(entry.name) + "}");
            int seen = 0;
            for (const Point2 film :
                 {Point2{0, 0}, Point2{100, 50}, Point2{199.99, 99.99}, Point2{120, 60}}) {
                for (const Point2 lens : {Point2{0, 0}, Point2{0.5, 0.5}, Point2{0.99, 0.3}}) {
                    const Ray r = scene.view.camera->generate_ray(film, lens);
                    ASSERT_TRUE(is_finite(r.origin));
                    ASSERT_TRUE(is_finite(r.direction));
                    if (sees_scene(r)) {
                        EXPECT_NEAR(length(r.direction), 1, 1e-12);
                        ++seen;
                    }
                }
            }
            EXPECT_GE(seen, 6);  // only a fisheye's corners may see nothing
        }
    }
}

TEST(AllCameras, RaysMadeTogetherAreTheRaysMadeOneByOne) {
    // The render loop asks for a batch's rays together (Camera::generate_rays); a camera that overrides it
    // (the pinhole's loop without virtual calls, the thin lens's AVX2 lanes) must give generate_ray's bits.
    for (const CameraEntry& entry : camera_table()) {
        SCOPED_TRACE(entry.name);
        const Scene scene =
            test::camera_scene("{type: " + entry.name + ", eye: [1, 2, 3], look_at: [0, 0, -1]" +
                               required_keys(entry.name) + "}");
        std::vector<Point2> film, lens;
        for (int i = 0; i < 7; ++i) {
            film.push_back({3.5 + 27.25 * i, 99.9 - 13.125 * i});
            lens.push_back({0.125 * i, 0.9 - 0.11 * i});
        }
        std::vector<Ray> together(film.size());
        scene.view.camera->generate_rays(film, lens, together);
        for (std::size_t i = 0; i < film.size(); ++i) {
            const Ray alone = scene.view.camera->generate_ray(film[i], lens[i]);
            EXPECT_EQ(together[i].origin, alone.origin) << i;
            EXPECT_EQ(together[i].direction, alone.direction) << i;
        }
    }
}

TEST(AllCameras, TheImageCentreLooksAtLookAt) {
    for (const CameraEntry& entry : camera_table()) {
        SCOPED_TRACE(entry.name);
        const Vec3 look_at{-2, 0.5, 0};
        const Scene scene =
            test::camera_scene("{type: " + entry.name + ", eye: [1, 2, 3], look_at: [-2, 0.5, 0]" +
                               required_keys(entry.name) + "}");
        for (const Point2 lens : {Point2{0.5, 0.5}, Point2{0.1, 0.8}}) {
            EXPECT_LT(test::distance_to_line(scene.view.camera->generate_ray({100, 50}, lens), look_at),
                      1e-12);
        }
    }
}

}  // namespace
}  // namespace glint
