#include "glint/image/tone_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace glint {

namespace {

// AgX, after Benjamin Wrensch's "Minimal AgX implementation" (iolite-engine.com, 2023, MIT), his
// polynomial fit of Troy Sobotka's AgX base curve (github.com/sobotka/AgX):
// 1. the "inset": a mix that moves every colour a little towards grey, so that very bright saturated
//    colours desaturate on their way to white instead of clipping to a pure hue;
// 2. log2 of each channel, clamped to the 16.5 stops [−12.47393, 4.026069] around middle grey, mapped
//    to [0, 1];
// 3. the sigmoid, as his degree-6 polynomial;
// 4. the inset undone (its inverse matrix; he rounds that inverse, glint computes it);
// 5. the result is display-encoded with a 2.2 power, so it is raised to 2.2 to give linear values.
using Matrix3 = std::array<std::array<double, 3>, 3>;
constexpr Matrix3 kAgxInset = {{{0.842479062253094, 0.0784335999999992, 0.0792237451477643},
                                {0.0423282422610123, 0.878468636469772, 0.0791661274605434},
                                {0.0423756549057051, 0.0784336, 0.879142973793104}}};
constexpr double kAgxMinEv = -12.47393;
constexpr double kAgxMaxEv = 4.026069;

Matrix3 inverse(const Matrix3& m) {
    const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    Matrix3 r{};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            // The cofactor of m[j][i], over the determinant.
            const int a = (j + 1) % 3, b = (j + 2) % 3, c = (i + 1) % 3, d = (i + 2) % 3;
            r[i][j] = (m[a][c] * m[b][d] - m[a][d] * m[b][c]) / det;
        }
    }
    return r;
}

Rgb multiply(const Matrix3& m, Rgb v) {
    return {m[0][0] * v.r + m[0][1] * v.g + m[0][2] * v.b, m[1][0] * v.r + m[1][1] * v.g + m[1][2] * v.b,
            m[2][0] * v.r + m[2][1] * v.g + m[2][2] * v.b};
}

double agx_contrast(double x) {  // Wrensch's fit of the AgX sigmoid on [0, 1]
    const double x2 = x * x, x4 = x2 * x2;
    return 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
}

double agx_encode(double x) {  // step 2 then 3, one channel
    const double ev = x > 0 ? std::clamp(std::log2(x), kAgxMinEv, kAgxMaxEv) : kAgxMinEv;
    return agx_contrast((ev - kAgxMinEv) / (kAgxMaxEv - kAgxMinEv));
}

Rgb agx(Rgb linear) {
    static const Matrix3 outset = inverse(kAgxInset);
    const Rgb inset = multiply(kAgxInset, linear);
    const Rgb curved = multiply(outset, Rgb(agx_encode(inset.r), agx_encode(inset.g), agx_encode(inset.b)));
    const auto to_linear = [](double encoded) { return std::pow(std::clamp(encoded, 0.0, 1.0), 2.2); };
    return {to_linear(curved.r), to_linear(curved.g), to_linear(curved.b)};
}

double finite_or_zero(double x) {
    return std::isnan(x) ? 0.0 : x;
}

}  // namespace

const EnumTable<ToneCurve>& tone_curve_table() {
    static const EnumTable<ToneCurve> table = {{"clamp", ToneCurve::Clamp},
                                               {"reinhard", ToneCurve::Reinhard},
                                               {"aces", ToneCurve::Aces},
                                               {"agx", ToneCurve::Agx}};
    return table;
}

double tone_curve(ToneCurve curve, double x) {
    if (!(x > 0)) {
        return 0;  // negative, zero or NaN
    }
    switch (curve) {
        case ToneCurve::Reinhard:
            return std::isinf(x) ? 1.0 : x / (1 + x);
        case ToneCurve::Aces: {
            // Narkowicz, "ACES Filmic Tone Mapping Curve" (2015): (x (a x + b)) / (x (c x + d) + e), fitted
            // to the ACES RRT + ODT for sRGB; it reaches 1 near x = 11.2 and is clamped past it.
            constexpr double a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
            return std::isinf(x) ? 1.0 : std::clamp(x * (a * x + b) / (x * (c * x + d) + e), 0.0, 1.0);
        }
        case ToneCurve::Agx:
            return agx(Rgb(x)).g;
        case ToneCurve::Clamp:
            break;
    }
    return std::min(x, 1.0);
}

Rgb tone_map_pixel(ToneCurve curve, Rgb linear) {
    if (curve == ToneCurve::Agx) {
        // Channels that are NaN or negative carry no light; +∞ is as bright as the curve goes.
        const auto clean = [](double x) { return x > 0 ? std::min(x, 1e300) : 0.0; };
        return agx(Rgb(clean(linear.r), clean(linear.g), clean(linear.b)));
    }
    return {tone_curve(curve, linear.r), tone_curve(curve, linear.g), tone_curve(curve, linear.b)};
}

Image to_display(const Image& linear, const DisplayTransform& transform) {
    Image out = linear;
    const double scale = std::exp2(transform.exposure);
    for (std::size_t i = 0; i + 2 < out.rgb.size(); i += 3) {
        float* p = &out.rgb[i];
        const Rgb mapped = tone_map_pixel(
            transform.curve,
            Rgb(finite_or_zero(p[0]) * scale, finite_or_zero(p[1]) * scale, finite_or_zero(p[2]) * scale));
        p[0] = static_cast<float>(mapped.r);
        p[1] = static_cast<float>(mapped.g);
        p[2] = static_cast<float>(mapped.b);
    }
    return out;
}

}  // namespace glint
