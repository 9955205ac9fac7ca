// What the shapes around an axis (cylinder, cone) share: a local frame whose z axis runs from the
// base centre along the axis, so each shape solves its equation in the simplest coordinates, and the
// flat round caps that close them.
#pragma once

#include "glint/core/frame.hpp"
#include "glint/core/ray.hpp"

namespace glint {

struct AxialFrame {
    Vec3 base;      // world position of the local origin
    Frame frame;    // frame.n: the unit axis (local z)
    double height;  // distance from base to the far end along the axis

    AxialFrame(const Vec3& base_, const Vec3& end)
        : base(base_), frame(Frame::from_normal(normalize(end - base_))), height(length(end - base_)) {}

    // The ray in local coordinates; t is unchanged (a rotation and a translation).
    Ray to_local(const Ray& ray) const {
        return {frame.to_local(ray.origin - base), frame.to_local(ray.direction)};
    }
    Vec3 point_to_world(const Vec3& p) const { return base + frame.to_world(p); }
    Vec3 vector_to_world(const Vec3& v) const { return frame.to_world(v); }
};

// A flat round cap of the local shape: the disk of `radius` around the axis at height z. The t of the
// hit in (0, t_max), or kInf.
inline double cap_hit_t(const Ray& local, double z, double radius, double t_max) {
    if (local.direction.z == 0) {
        return kInf;  // edge-on
    }
    const double t = (z - local.origin.z) / local.direction.z;
    if (!(t > 0) || t >= t_max) {
        return kInf;
    }
    const double x = local.origin.x + t * local.direction.x;
    const double y = local.origin.y + t * local.direction.y;
    return x * x + y * y <= radius * radius ? t : kInf;
}

// u coordinate of a point around the local z axis: the angle over 2π, in [0, 1).
inline double angle_fraction(double x, double y) {
    const double phi = std::atan2(y, x);
    return (phi < 0 ? phi + 2 * kPi : phi) / (2 * kPi);
}

}  // namespace glint
