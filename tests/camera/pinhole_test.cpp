#include <gtest/gtest.h>

#include "glint/camera/camera.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

void expect_orthonormal_right_handed(const CameraBasis& b) {
    EXPECT_NEAR(length(b.u), 1, 1e-12);
    EXPECT_NEAR(length(b.v), 1, 1e-12);
    EXPECT_NEAR(length(b.w), 1, 1e-12);
    EXPECT_NEAR(dot(b.u, b.v), 0, 1e-12);
    EXPECT_NEAR(dot(b.v, b.w), 0, 1e-12);
    EXPECT_NEAR(dot(b.w, b.u), 0, 1e-12);
    EXPECT_NEAR(length(cross(b.u, b.v) - b.w), 0, 1e-12);
}

TEST(CameraBasis, FollowsTheErrataFormulas) {
    struct Case {
        Vec3 eye, look_at, up;
    };
    const Case cases[] = {
        {{0, 0, 5}, {0, 0, 0}, {0, 1, 0}},   {{3, 2, 1}, {0, 0, 0}, {0, 1, 0}},
        {{0, 10, 10}, {0, 0, 0}, {0, 1, 0}}, {{1, 1, 1}, {2, -3, 4}, {0.3, 1, 0.2}},
        {{0, 0, 0}, {-5, 0, 0}, {0, 0, 1}},
    };
    for (const Case& c : cases) {
        const CameraBasis b = camera_basis(c.eye, c.look_at, c.up);
        EXPECT_FALSE(b.up_was_degenerate);
        expect_orthonormal_right_handed(b);
        // w = (e − l)/‖e − l‖, u = (up × w)/‖up × w‖, v = w × u.
        EXPECT_NEAR(length(b.w - normalize(c.eye - c.look_at)), 0, 1e-12);
        EXPECT_NEAR(length(b.u - normalize(cross(c.up, b.w))), 0, 1e-12);
        EXPECT_NEAR(length(b.v - cross(b.w, b.u)), 0, 1e-12);
        // up sets the roll: v leans towards up.
        EXPECT_GT(dot(b.v, c.up), 0);
    }
}

TEST(CameraBasis, DegenerateUpLookingStraightDownOrUpGivesAValidBasis) {
    const CameraBasis down = camera_basis({0, 10, 0}, {0, 0, 0}, {0, 1, 0});
    EXPECT_TRUE(down.up_was_degenerate);
    expect_orthonormal_right_handed(down);
    EXPECT_NEAR(length(down.v - Vec3(0, 0, -1)), 0, 1e-12);  // the top of the image is −z

    const CameraBasis up = camera_basis({0, 0, 0}, {0, 3, 0}, {0, 1, 0});
    EXPECT_TRUE(up.up_was_degenerate);
    expect_orthonormal_right_handed(up);
    EXPECT_NEAR(length(up.v - Vec3(0, 0, 1)), 0, 1e-12);

    const CameraBasis sideways = camera_basis({0, 0, 0}, {4, 0, 0}, {-2, 0, 0});
    EXPECT_TRUE(sideways.up_was_degenerate);
    expect_orthonormal_right_handed(sideways);
}

Scene camera_scene(const std::string& camera, int width = 200, int height = 100) {
    return test::scene_from_text("render: {width: " + std::to_string(width) +
                                 ", height: " + std::to_string(height) + "}\ncamera: " + camera + "\n");
}

TEST(Pinhole, TheImageCentreLooksAtLookAt) {
    const Scene scene = camera_scene("{eye: [1, 2, 3], look_at: [-2, 0.5, 0], fov: 50}");
    const Ray r = scene.view.camera->generate_ray({100, 50}, {0.5, 0.5});
    EXPECT_EQ(r.origin, Vec3(1, 2, 3));
    EXPECT_NEAR(length(normalize(r.direction) - normalize(Vec3(-2, 0.5, 0) - Vec3(1, 2, 3))), 0, 1e-12);
}

TEST(Pinhole, VerticalFieldOfViewSpansTheImageHeight) {
    const Scene scene = camera_scene("{eye: [0, 0, 0], look_at: [0, 0, -1], fov: 90}");
    // The top edge of the image is 45° above the axis; the right edge at atan(2) with a 2:1 image.
    const Vec3 top = normalize(scene.view.camera->generate_ray({100, 0}, {}).direction);
    EXPECT_NEAR(top.y, std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(top.z, -std::sqrt(0.5), 1e-12);
    const Vec3 right = normalize(scene.view.camera->generate_ray({200, 50}, {}).direction);
    EXPECT_NEAR(std::atan2(right.x, -right.z), std::atan(2.0), 1e-12);
}

TEST(Pinhole, KnownWorldPointProjectsToTheExpectedPixel) {
    // The paper's parametrisation: view-plane distance d = 100 pixels, zoom 1. A point at (x, y, −z)
    // lands at pixel (w/2 + d·x/z, h/2 − d·y/z).
    const Scene scene = camera_scene("{eye: [0, 0, 0], look_at: [0, 0, -1], view_distance: 100}");
    const Vec3 point{1.5, -0.5, -5};
    const Point2 pixel{100 + 100 * 1.5 / 5, 50 + 100 * 0.5 / 5};
    const Ray r = scene.view.camera->generate_ray(pixel, {});
    const Vec3 d = normalize(r.direction);
    EXPECT_NEAR(length(d - normalize(point)), 0, 1e-12);
    // zoom 2 halves the pixel size: the same point is twice as far from the centre.
    const Scene zoomed = camera_scene("{eye: [0, 0, 0], look_at: [0, 0, -1], view_distance: 100, zoom: 2}");
    const Ray rz = zoomed.view.camera->generate_ray({100 + 200 * 1.5 / 5, 50 + 200 * 0.5 / 5}, {});
    EXPECT_NEAR(length(normalize(rz.direction) - normalize(point)), 0, 1e-12);
}

}  // namespace
}  // namespace glint
