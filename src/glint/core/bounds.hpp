#pragma once

#include "glint/core/vec.hpp"

namespace glint {

// An axis-aligned box. The default box is empty (min > max) so that growing it by points works.
struct Bounds3 {
    Vec3 lo{kInf, kInf, kInf};
    Vec3 hi{-kInf, -kInf, -kInf};

    static Bounds3 infinite() { return {Vec3{-kInf, -kInf, -kInf}, Vec3{kInf, kInf, kInf}}; }

    void grow(const Vec3& p) {
        lo = min(lo, p);
        hi = max(hi, p);
    }
    void grow(const Bounds3& b) {
        lo = min(lo, b.lo);
        hi = max(hi, b.hi);
    }
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    bool is_finite() const { return glint::is_finite(lo) && glint::is_finite(hi); }
    Vec3 extent() const { return hi - lo; }
    Vec3 center() const { return 0.5 * (lo + hi); }
};

}  // namespace glint
