// Scalar helpers and constants shared by every part of glint.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

namespace glint {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kInvPi = 1.0 / std::numbers::pi;
inline constexpr double kInf = std::numeric_limits<double>::infinity();

constexpr double sqr(double x) {
    return x * x;
}
inline double radians(double degrees) {
    return degrees * (kPi / 180.0);
}
inline double degrees(double radians) {
    return radians * (180.0 / kPi);
}
// sqrt that treats the tiny negative values rounding produces as zero instead of returning NaN.
inline double safe_sqrt(double x) {
    return std::sqrt(std::max(0.0, x));
}
inline double lerp(double t, double a, double b) {
    return a + t * (b - a);
}

}  // namespace glint
