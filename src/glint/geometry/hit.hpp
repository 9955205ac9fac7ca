#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "glint/core/math.hpp"
#include "glint/core/ray.hpp"

namespace glint {

// Where a ray met a surface.
struct Hit {
    double t = kInf;      // ray parameter
    Vec3 point;           // world position
    Vec3 normal;          // unit geometric normal; for closed shapes it points outwards
    Vec3 shading_normal;  // unit normal used for shading (interpolated on meshes); same side as `normal`
    // Surface parametrisation, for textures: read it through surface_uv(hit), never directly. A sphere
    // leaves kUvFromSphereNormal here instead of its uv (an atan2 and an acos for every nearest hit, which
    // most materials never read), and surface_uv computes the uv from `normal` when asked.
    Point2 uv;
    // Bound on the absolute error of `point` in each axis. Rays leaving the surface start this far off
    // it, so that no epsilon in scene units is needed and scaled scenes behave the same.
    double error = 0;
    std::uint32_t primitive = 0;  // index into the scene's primitives
    std::uint32_t element = 0;    // which part of that primitive was hit: the triangle of a mesh
};

// The uv a sphere gives its hits, from the unit normal n (outwards, in the sphere's own space): u the
// angle about +y from +x towards +z over 2π, in [0, 1); v the angle from +y over π, in [0, 1].
inline Point2 sphere_uv(const Vec3& n) {
    const double phi = std::atan2(n.z, n.x);
    return {(phi < 0 ? phi + 2 * kPi : phi) / (2 * kPi), std::acos(std::clamp(n.y, -1.0, 1.0)) / kPi};
}

// The marker in Hit::uv of a uv not computed yet: NaN, which no shape's uv is. Any shape that records a
// hit writes its uv over it, so a hit record reused by the next nearer shape never keeps the marker.
inline constexpr Point2 kUvFromSphereNormal{std::numeric_limits<double>::quiet_NaN(), 0};

inline bool uv_deferred(const Hit& hit) {
    return std::isnan(hit.uv.x);
}

// The hit's uv: the one its shape recorded, or, for a sphere, the one its normal gives. A wrapper that
// moves the normal out of the shape's space (Instance) resolves the uv first.
inline Point2 surface_uv(const Hit& hit) {
    return uv_deferred(hit) ? sphere_uv(hit.normal) : hit.uv;
}

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
