#pragma once

#include <cstdint>

#include "glint/core/math.hpp"
#include "glint/core/ray.hpp"

namespace glint {

// Where a ray met a surface.
struct Hit {
    double t = kInf;      // ray parameter
    Vec3 point;           // world position
    Vec3 normal;          // unit geometric normal; for closed shapes it points outwards
    Vec3 shading_normal;  // unit normal used for shading (interpolated on meshes); same side as `normal`
    Point2 uv;            // surface parametrisation, for textures
    // Bound on the absolute error of `point` in each axis. Rays leaving the surface start this far off
    // it, so that no epsilon in scene units is needed and scaled scenes behave the same.
    double error = 0;
    std::uint32_t primitive = 0;  // index into the scene's primitives
    std::uint32_t element = 0;    // which part of that primitive was hit: the triangle of a mesh
};

// Relative rounding error of hit points computed in double precision, with a wide margin: hit points
// are projected back onto their surface, so their error is a few ulps of the coordinates involved.
inline constexpr double kHitRelativeError = 1e-11;

// The origin for a ray leaving the surface at `hit` in direction `dir`: the hit point pushed along the
// normal, to the side `dir` goes, by just more than the point's error bound (pbrt's offset ray origin).
inline Vec3 offset_ray_origin(const Hit& hit, const Vec3& dir) {
    const double d = hit.error * (std::abs(hit.normal.x) + std::abs(hit.normal.y) + std::abs(hit.normal.z));
    const Vec3 offset = hit.normal * d;
    return dot(dir, hit.normal) >= 0 ? hit.point + offset : hit.point - offset;
}

inline Ray spawn_ray(const Hit& hit, const Vec3& dir) {
    return {offset_ray_origin(hit, dir), dir};
}

// A ray from `hit` towards the point `target`, parametrised so that t = 1 reaches the target.
inline Ray spawn_ray_to(const Hit& hit, const Vec3& target) {
    const Vec3 origin = offset_ray_origin(hit, target - hit.point);
    return {origin, target - origin};
}

}  // namespace glint
