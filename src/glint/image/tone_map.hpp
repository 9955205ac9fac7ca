// From the film's linear radiance to what an 8-bit image can show: an exposure, then a tone curve that
// brings every value into [0, 1] (docs/scene-format.md, `render.exposure` and `render.tonemap`). Applied
// to PNG output and the preview only; EXR and PFM keep exactly what the film holds.
#pragma once

#include "glint/core/color.hpp"
#include "glint/image/image.hpp"
#include "glint/params/name_table.hpp"

namespace glint {

enum class ToneCurve {
    Clamp,     // min(x, 1): the paper's images, and glint's default
    Reinhard,  // x / (1 + x), per channel (Reinhard et al. 2002, eq. 3)
    Aces,      // Narkowicz's 2015 fit of the ACES reference rendering transform, per channel
    // Sobotka's AgX base (Blender 4's default view) in Wrensch's minimal form: a mix of the channels,
    // a log encoding over 16.5 stops, a sigmoid, the mix undone. Per pixel, not per channel: bright
    // saturated colours go towards white instead of clipping to a hue.
    Agx,
};

// The curves by name, as render.tonemap, --tonemap and the preview's control say them.
const EnumTable<ToneCurve>& tone_curve_table();
// The largest exposure, in stops either way, that render.exposure and the preview take.
inline constexpr double kMaxExposureStops = 64;

struct DisplayTransform {
    double exposure = 0;  // in stops (EV): radiance is multiplied by 2^exposure before the curve
    ToneCurve curve = ToneCurve::Clamp;
};

// The curve at one value (x ≥ 0 after exposure); the result is in [0, 1]. For a curve that mixes the
// channels (AgX) this is its value on grey, x in all three.
double tone_curve(ToneCurve curve, double x);

// The curve at one pixel (linear RGB after exposure): each channel in [0, 1], linear.
Rgb tone_map_pixel(ToneCurve curve, Rgb linear);

// The image scaled by 2^exposure and passed through the curve, channel by channel; NaN becomes 0.
Image to_display(const Image& linear, const DisplayTransform& transform);

}  // namespace glint
