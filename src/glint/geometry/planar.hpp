// What the flat shapes (disk, annulus, rectangle, the caps of cylinders and cones) share: where a ray
// meets their plane, and the hit point put back exactly onto that plane.
#pragma once

#include "glint/core/bounds.hpp"
#include "glint/core/ray.hpp"

namespace glint {

// The t at which `ray` meets the plane through `point` with normal `normal` (any length); infinite
// when the ray is parallel to the plane, even if it lies in it (a flat shape seen edge-on is not hit).
inline double plane_hit_t(const Ray& ray, const Vec3& point, const Vec3& normal) {
    const double denominator = dot(ray.direction, normal);
    if (denominator == 0) {
        return kInf;
    }
    return dot(point - ray.origin, normal) / denominator;
}

// ray.at(t) moved along the unit `normal` onto the plane, so its error does not grow with t.
inline Vec3 point_on_plane(const Ray& ray, double t, const Vec3& point, const Vec3& normal) {
    const Vec3 p = ray.at(t);
    return p - normal * dot(p - point, normal);
}

// Bounds of the disk of `radius` around `center` in the plane of the unit `normal`: along axis i the
// disk reaches radius · sin(angle between axis i and the normal) = radius · √(1 − n_i²).
inline Bounds3 disk_bounds(const Vec3& center, const Vec3& normal, double radius) {
    const Vec3 half{radius * safe_sqrt(1 - normal.x * normal.x), radius * safe_sqrt(1 - normal.y * normal.y),
                    radius * safe_sqrt(1 - normal.z * normal.z)};
    return {center - half, center + half};
}

}  // namespace glint
