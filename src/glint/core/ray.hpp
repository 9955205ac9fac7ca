#pragma once

#include "glint/core/vec.hpp"

namespace glint {

// A half-line origin + t·direction. The direction need not be unit length; every shape returns t in
// the units of this parametrisation, so a hit distance is t·|direction|.
struct Ray {
    Vec3 origin;
    Vec3 direction;

    constexpr Vec3 at(double t) const { return origin + t * direction; }
};

}  // namespace glint
