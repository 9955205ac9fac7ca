// Orthonormal bases: the shading frame around a normal, and the camera's (u, v, w).
#pragma once

#include "glint/core/vec.hpp"

namespace glint {

struct Frame {
    Vec3 s, t, n;  // tangent, bitangent, normal: right-handed, s × t = n

    // A frame around the unit vector n, without branches on the axis and without a singularity
    // (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017).
    static Frame from_normal(const Vec3& n) {
        const double sign = std::copysign(1.0, n.z);
        const double a = -1.0 / (sign + n.z);
        const double b = n.x * n.y * a;
        return {Vec3{1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x}, Vec3{b, sign + n.y * n.y * a, -n.y},
                n};
    }

    Vec3 to_local(const Vec3& v) const { return {dot(v, s), dot(v, t), dot(v, n)}; }
    Vec3 to_world(const Vec3& v) const { return v.x * s + v.y * t + v.z * n; }
};

}  // namespace glint
