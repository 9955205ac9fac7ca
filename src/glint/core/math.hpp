// Scalar helpers and constants shared by every part of glint.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
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

struct SinCos {
    double sin;
    double cos;
};

// sin x and cos x for |x| ≤ π/4, by their Taylor series to x¹⁵ and x¹⁶: the first term left out is
// below 7e-17 relative there, under half an ulp. A few multiply-adds instead of the library's general
// argument reduction, for the sampling code that needs sines and cosines of angles it chose itself.
// The series in y = x² are evaluated in pairs of terms weighted by y² and y⁴ (Estrin's scheme), not
// by Horner's rule: about half the chain of dependent operations, which is what the sampling code
// waits for. Summing the small terms first and adding 1 last keeps the accuracy of Horner's rule:
// within 1.4 ulp of the exact sine and 1 ulp of the exact cosine (Horner's: 1.4 and 1.2), and within
// 2 ulps of Horner's results (tests/core/math_test.cpp). The thin lens repeats it in AVX2 lanes,
// operation for operation (camera/thin_lens.cpp, sincos_quarter_pi_lanes): change both together.
inline SinCos sincos_quarter_pi(double x) {
    const double y = x * x;
    const double y2 = y * y;
    const double y4 = y2 * y2;
    const double sin_high =
        (1.0 / 362880 + y * (-1.0 / 39916800)) + y2 * (1.0 / 6227020800 + y * (-1.0 / 1307674368000));
    const double sin_tail = y * (-1.0 / 6) + (y2 * (1.0 / 120 + y * (-1.0 / 5040)) + y4 * sin_high);
    const double cos_high = (1.0 / 40320 + y * (-1.0 / 3628800)) +
                            y2 * (1.0 / 479001600 + y * (-1.0 / 87178291200)) + y4 * (1.0 / 20922789888000);
    const double cos_tail = y * (-1.0 / 2) + (y2 * (1.0 / 24 + y * (-1.0 / 720)) + y4 * cos_high);
    return {x * (1 + sin_tail), 1 + cos_tail};
}

// sin and cos of 2π·turns, for 0 ≤ turns < 2²⁹: the azimuth of a sample, φ = 2π u. The nearest
// quarter turn q/4 is taken off exactly (Sterbenz: turns and q/4 are within a factor of 2), which leaves
// |x| ≤ π/4 for sincos_quarter_pi, and the quarter turn is put back by swapping and negating, without
// branches (the quadrant of a random sample is unpredictable). Near the zeros (u = ¼, ½, …) it even
// keeps the small value's relative accuracy, which std::cos(2π u) loses to the rounding of 2π u.
inline SinCos sincos_turns(double turns) {
    const auto quadrant = static_cast<std::int32_t>(4 * turns + 0.5);
    const double rest = turns - 0.25 * quadrant;  // exact, in [−⅛, ⅛]
    const SinCos near = sincos_quarter_pi(2 * kPi * rest);
    // sin(qπ/2 + x), cos(qπ/2 + x): odd q swaps sin and cos; sin is negated for q = 2, 3 (mod 4) and
    // cos for q = 1, 2.
    const bool odd = (quadrant & 1) != 0;
    const double sin_sign = (quadrant & 2) != 0 ? -1.0 : 1.0;
    const double cos_sign = ((quadrant + 1) & 2) != 0 ? -1.0 : 1.0;
    return {sin_sign * (odd ? near.cos : near.sin), cos_sign * (odd ? near.sin : near.cos)};
}

}  // namespace glint
