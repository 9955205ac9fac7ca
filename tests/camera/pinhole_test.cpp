#include <gtest/gtest.h>

#include "camera/camera_test_util.hpp"

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

using test::camera_scene;
using test::kObliqueEye;
using test::kObliqueForward;
using test::kObliqueView;

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

TEST(Pinhole, NearPlaneStartsRaysWhereTheyCrossIt) {
    // The near-0 ray through each film point, started on the plane across the view at depth 2: its
    // origin is where that ray reaches depth 2 (origin·forward = 2, on the same line), direction kept.
    const Scene plain = camera_scene("{" + kObliqueView + "}");
    const Scene clipped = camera_scene("{" + kObliqueView + ", near: 2}");
    const Vec3& eye = kObliqueEye;
    const Vec3& forward = kObliqueForward;
    for (const Point2 film : {Point2{100, 50}, Point2{0, 0}, Point2{199.9, 3.25}, Point2{17.5, 99.9}}) {
        const Ray from_eye = plain.view.camera->generate_ray(film, {});
        const Ray from_near = clipped.view.camera->generate_ray(film, {});
        EXPECT_NEAR(dot(from_near.origin - eye, forward), 2, 1e-12);
        EXPECT_LT(length(from_near.origin - test::at_depth(from_eye, eye, forward, 2)), 1e-12);
        EXPECT_LT(length(from_near.direction - from_eye.direction), 1e-15);
    }
    // Unset, and 0, are today's camera bit for bit.
    const Scene zero = camera_scene("{" + kObliqueView + ", near: 0}");
    const Ray a = zero.view.camera->generate_ray({33.3, 44.4}, {});
    const Ray b = plain.view.camera->generate_ray({33.3, 44.4}, {});
    EXPECT_EQ(a.origin, b.origin);
    EXPECT_EQ(a.direction, b.direction);
}

TEST(Pinhole, NearSphereStartsRaysAtTheNearDistanceAlongThemselves) {
    const Scene plain = camera_scene("{" + kObliqueView + "}");
    const Scene clipped = camera_scene("{" + kObliqueView + ", near: 2, near_shape: sphere}");
    const Vec3& eye = kObliqueEye;
    for (const Point2 film : {Point2{100, 50}, Point2{0, 0}, Point2{199.9, 3.25}}) {
        const Ray from_eye = plain.view.camera->generate_ray(film, {});
        const Ray from_near = clipped.view.camera->generate_ray(film, {});
        EXPECT_LT(length(from_near.origin - (eye + 2 * from_eye.direction)), 1e-12);
        EXPECT_EQ(from_near.direction, from_eye.direction);
    }
}

// The colour of the image centre of an emissive wall at depth 1 in front of one at depth 5, seen by a
// camera with the given near plane.
Rgb centre_seen_with_near(double near) {
    const Scene scene = test::scene_from_text(R"(
render: {width: 4, height: 4, samples: 1, integrator: raycast}
camera: {eye: [0, 0, 0], look_at: [0, 0, -1], fov: 40, near: )" +
                                              std::to_string(near) + R"(}
objects:
  - {type: rectangle, corner: [-5, -5, -1], edge1: [10, 0, 0], edge2: [0, 10, 0],
     material: {type: emissive, radiance: [1, 0, 0], two_sided: true}}
  - {type: rectangle, corner: [-50, -50, -5], edge1: [100, 0, 0], edge2: [0, 100, 0],
     material: {type: emissive, radiance: [0, 0, 1], two_sided: true}}
)");
    return test::render_film(scene).pixel(2, 2);
}

TEST(Pinhole, NothingNearerThanTheNearPlaneIsSeen) {
    EXPECT_EQ(centre_seen_with_near(0), Rgb(1, 0, 0));    // the near wall hides the far one
    EXPECT_EQ(centre_seen_with_near(0.9), Rgb(1, 0, 0));  // the near plane in front of the wall
    EXPECT_EQ(centre_seen_with_near(2), Rgb(0, 0, 1));    // past it: only the far wall is seen
}

TEST(Pinhole, RejectsANegativeOrNonNumericNear) {
    EXPECT_NE(test::camera_error("{near: -1}").find("camera.near must be zero or more"), std::string::npos);
    EXPECT_NE(test::camera_error("{near: .inf}").find("camera.near must be"), std::string::npos);
    EXPECT_NE(test::camera_error("{near: far}").find("camera.near must be a number"), std::string::npos);
    EXPECT_NE(test::camera_error("{near: 1, near_shape: cube}").find("camera.near_shape is 'cube'"),
              std::string::npos);
}

}  // namespace
}  // namespace glint
