// What the flat shapes (disk, annulus, rectangle, the caps of cylinders and cones) share: where a ray
// meets their plane, and the hit point put back exactly onto that plane.
#pragma once

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

}  // namespace glint
