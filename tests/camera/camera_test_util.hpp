// Helpers shared by the camera tests.
#pragma once

#include <string>

#include "glint/camera/camera.hpp"
#include "glint/params/diagnostics.hpp"
#include "test_util.hpp"

namespace glint::test {

// A scene holding only a camera (given as a YAML flow map) and an image size.
inline Scene camera_scene(const std::string& camera, int width = 200, int height = 100) {
    return scene_from_text("render: {width: " + std::to_string(width) +
                           ", height: " + std::to_string(height) + "}\ncamera: " + camera + "\n");
}

// The message of the error building a camera (given as a YAML flow map) gives, or "no error".
inline std::string camera_error(const std::string& camera) {
    try {
        camera_scene(camera);
    } catch (const SceneError& e) {
        return e.message();
    }
    return "no error";
}

// An oblique view the camera tests share: its keys (to put in a camera's map), its eye and its unit view
// direction, so that a test can check depths along the view without restating the numbers.
inline const std::string kObliqueView = "eye: [1, 2, 3], look_at: [-2, 0.5, -1], fov: 50";
inline const Vec3 kObliqueEye{1, 2, 3};
inline const Vec3 kObliqueForward = normalize(Vec3(-2, 0.5, -1) - kObliqueEye);

// The distance from `point` to the line of `ray` (both ways), for "does this ray pass through p".
inline double distance_to_line(const Ray& ray, const Vec3& point) {
    const Vec3 d = normalize(ray.direction);
    const Vec3 to_point = point - ray.origin;
    return length(to_point - dot(to_point, d) * d);
}

// Where `ray` crosses the plane across `forward` (unit) at `depth` in front of `eye`.
inline Vec3 at_depth(const Ray& ray, const Vec3& eye, const Vec3& forward, double depth) {
    const double t = (depth - dot(ray.origin - eye, forward)) / dot(ray.direction, forward);
    return ray.at(t);
}

}  // namespace glint::test
