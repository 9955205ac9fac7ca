#include "glint/image/tone_map.hpp"

#include <algorithm>
#include <cmath>

namespace glint {

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
        case ToneCurve::Clamp:
            break;
    }
    return std::min(x, 1.0);
}

Image to_display(const Image& linear, const DisplayTransform& transform) {
    Image out = linear;
    const double scale = std::exp2(transform.exposure);
    for (float& value : out.rgb) {
        value = static_cast<float>(tone_curve(transform.curve, static_cast<double>(value) * scale));
    }
    return out;
}

}  // namespace glint
