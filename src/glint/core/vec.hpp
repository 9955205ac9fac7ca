// Vectors and points in 3-D (double precision: robust intersection without per-shape error analysis)
// and 2-D sample points.
#pragma once

#include <cmath>
#include <ostream>

#include "glint/core/math.hpp"

namespace glint {

struct Vec3 {
    double x = 0, y = 0, z = 0;

    constexpr Vec3() = default;
    constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

    constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3 operator-() const { return {-x, -y, -z}; }
    constexpr Vec3& operator+=(const Vec3& o) {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    constexpr Vec3& operator-=(const Vec3& o) {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    constexpr Vec3& operator*=(double s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    friend constexpr bool operator==(const Vec3&, const Vec3&) = default;
};

constexpr Vec3 operator+(Vec3 a, const Vec3& b) {
    return a += b;
}
constexpr Vec3 operator-(Vec3 a, const Vec3& b) {
    return a -= b;
}
constexpr Vec3 operator*(Vec3 a, double s) {
    return a *= s;
}
constexpr Vec3 operator*(double s, Vec3 a) {
    return a *= s;
}
constexpr Vec3 operator/(const Vec3& a, double s) {
    return a * (1.0 / s);
}
constexpr Vec3 hadamard(const Vec3& a, const Vec3& b) {
    return {a.x * b.x, a.y * b.y, a.z * b.z};
}

constexpr double dot(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr double length_squared(const Vec3& v) {
    return dot(v, v);
}
inline double length(const Vec3& v) {
    return std::sqrt(dot(v, v));
}
inline Vec3 normalize(const Vec3& v) {
    return v / length(v);
}
// normalize(v) for a v that is a unit vector up to its rounding (a sphere's radius vector over its
// radius), without the square root and the division, whose latency stood on the way from one ray to the
// next: |v|² = 1 + e, and one Newton step for 1/sqrt(1 + e), 1 − e/2, is off by about 3e²/8, below
// 2^-55 when |e| < 2^-27; the rounding of e and of the products then leaves a few ulps, as normalize's
// own. Any other v takes normalize.
inline Vec3 normalize_near_unit(const Vec3& v) {
    const double excess = dot(v, v) - 1;
    return std::abs(excess) < 0x1p-27 ? v * (1 - 0.5 * excess) : normalize(v);
}
inline Vec3 abs(const Vec3& v) {
    return {std::abs(v.x), std::abs(v.y), std::abs(v.z)};
}
inline double max_component(const Vec3& v) {
    return std::max({v.x, v.y, v.z});
}
inline double min_component(const Vec3& v) {
    return std::min({v.x, v.y, v.z});
}
inline Vec3 min(const Vec3& a, const Vec3& b) {
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
inline Vec3 max(const Vec3& a, const Vec3& b) {
    return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
inline bool is_finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Mirror reflection of the incident direction `i` (pointing towards the surface) about the normal `n`:
// R = I − 2 (I·N) N (paper eq. 16).
constexpr Vec3 reflect(const Vec3& i, const Vec3& n) {
    return i - 2.0 * dot(i, n) * n;
}

inline std::ostream& operator<<(std::ostream& os, const Vec3& v) {
    return os << '(' << v.x << ", " << v.y << ", " << v.z << ')';
}

// A point of the unit square [0,1)², or any 2-D coordinate (film positions in pixels).
struct Point2 {
    double x = 0, y = 0;
    friend constexpr bool operator==(const Point2&, const Point2&) = default;
};

}  // namespace glint
