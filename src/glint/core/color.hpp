// Linear RGB radiance and reflectance.
#pragma once

#include <cmath>
#include <ostream>

namespace glint {

struct Rgb {
    double r = 0, g = 0, b = 0;

    constexpr Rgb() = default;
    constexpr Rgb(double r_, double g_, double b_) : r(r_), g(g_), b(b_) {}
    constexpr explicit Rgb(double grey) : r(grey), g(grey), b(grey) {}

    constexpr double operator[](int i) const { return i == 0 ? r : (i == 1 ? g : b); }
    constexpr Rgb& operator+=(const Rgb& o) {
        r += o.r;
        g += o.g;
        b += o.b;
        return *this;
    }
    constexpr Rgb& operator*=(const Rgb& o) {
        r *= o.r;
        g *= o.g;
        b *= o.b;
        return *this;
    }
    constexpr Rgb& operator*=(double s) {
        r *= s;
        g *= s;
        b *= s;
        return *this;
    }
    constexpr bool is_black() const { return r == 0 && g == 0 && b == 0; }
    constexpr double max_component() const { return r > g ? (r > b ? r : b) : (g > b ? g : b); }
    // Rec. 709 / sRGB luminance of linear RGB.
    constexpr double luminance() const { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }
    bool is_finite() const { return std::isfinite(r) && std::isfinite(g) && std::isfinite(b); }
    friend constexpr bool operator==(const Rgb&, const Rgb&) = default;
};

constexpr Rgb operator+(Rgb a, const Rgb& b) {
    return a += b;
}
constexpr Rgb operator-(const Rgb& a, const Rgb& b) {
    return {a.r - b.r, a.g - b.g, a.b - b.b};
}
constexpr Rgb operator*(Rgb a, const Rgb& b) {
    return a *= b;
}
constexpr Rgb operator*(Rgb a, double s) {
    return a *= s;
}
constexpr Rgb operator*(double s, Rgb a) {
    return a *= s;
}
constexpr Rgb operator/(const Rgb& a, double s) {
    return a * (1.0 / s);
}

inline std::ostream& operator<<(std::ostream& os, const Rgb& c) {
    return os << '(' << c.r << ", " << c.g << ", " << c.b << ')';
}

}  // namespace glint
