#include "glint/material/microfacet.hpp"

#include <algorithm>

#include "glint/material/material.hpp"

namespace glint {

Vec3 GgxDistribution::sample_reflection(const Vec3& wo, Point2 u) const {
    // Visible normals with wo turned above the surface: stretch wo to the unit-roughness configuration,
    // sample the projected hemisphere seen from it, and unstretch the normal.
    const Vec3 o = flip_if_below(wo, wo.z);
    const Vec3 vh = normalize(Vec3{alpha_ * o.x, alpha_ * o.y, o.z});
    const double len2 = vh.x * vh.x + vh.y * vh.y;
    const Vec3 t1 = len2 > 0 ? Vec3{-vh.y, vh.x, 0} / std::sqrt(len2) : Vec3{1, 0, 0};
    const Vec3 t2 = cross(vh, t1);
    const double r = std::sqrt(u.x);
    const SinCos phi = sincos_turns(u.y);
    const double p1 = r * phi.cos;
    const double s = 0.5 * (1 + vh.z);
    const double p2 = (1 - s) * safe_sqrt(1 - p1 * p1) + s * r * phi.sin;
    const Vec3 nh = p1 * t1 + p2 * t2 + safe_sqrt(1 - p1 * p1 - p2 * p2) * vh;
    const Vec3 m = normalize(Vec3{alpha_ * nh.x, alpha_ * nh.y, std::max(1e-12, nh.z)});
    return flip_if_below(2 * dot(o, m) * m - o, wo.z);
}

}  // namespace glint
