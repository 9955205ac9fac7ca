#pragma once

#include "glint/image/tone_map.hpp"

#include <cstdint>
#include <optional>
#include <string>

#include "glint/sampling/pixel_filter.hpp"

namespace glint {

// Upper bounds of the render settings, checked by the scene builder for the file and the command line
// alike (docs/scene-format.md, "Limits"), each with the reason in its message:
// - a side of at most 32768 pixels and at most 2^27 pixels in all (16384 × 8192): the film holds 32
//   bytes a pixel, so the largest film is 4 GiB;
// - at most 2^20 samples per pixel: sample indices and the samplers' tables stay within 32 bits;
// - at most 1024 bounces: beyond that even a white mirror room's paths carry less than any float
//   difference, and Whitted's stack of pending branches stays small.
inline constexpr int kMaxFilmSide = 1 << 15;
inline constexpr std::int64_t kMaxFilmPixels = std::int64_t{1} << 27;
inline constexpr std::uint32_t kMaxSamplesPerPixel = 1u << 20;
inline constexpr int kMaxPathDepth = 1024;

// The message for a depth past kMaxPathDepth, the same wherever it is given.
inline std::string max_depth_limit_message(const std::string& what) {
    return what + " is more than " + std::to_string(kMaxPathDepth) +
           " bounces (paths that long carry no visible light, and every bounce costs time)";
}

// How to render: the scene's `render:` block with the command line's overrides applied.
// A rectangle of pixels: columns [x0, x1) and rows [y0, y1), from the top-left pixel.
struct PixelWindow {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool operator==(const PixelWindow&) const = default;
};

struct RenderSettings {
    int width = 640;
    int height = 360;
    std::uint32_t samples_per_pixel = 16;  // requested; the sampler may round it (jittered: to a square)
    // Owen-scrambled Sobol: on the reference scenes (smallpt, RTIOW's final scene, the Cornell box) it
    // has the lowest error per unit time of the patterns, and it takes any sample count as is.
    std::string sampler = "sobol";
    PixelFilter filter;  // where in and around its pixel a sample lands (box: the pixel itself)
    std::string integrator = "raycast";
    std::string accelerator = "bvh";
    int max_depth = 5;  // the integrator's, unless it gives its own
    std::uint64_t seed = 1;
    int threads = 0;     // 0: all cores
    int tile_size = 16;  // pixels per tile side; the image does not depend on it
    // Only these pixels are rendered (`render.crop`); each gets exactly the samples it gets in the
    // full render, so the window is bit for bit that part of the full image. Unset: the whole film.
    std::optional<PixelWindow> crop;
    // The pixels a render takes: the crop, else the whole image.
    PixelWindow rendered_window() const { return crop.value_or(PixelWindow{0, 0, width, height}); }
    // Firefly clamp: a sample brighter than this (its largest channel) is scaled down to it, keeping its
    // hue. Biased (it removes energy), so 0, off, by default.
    double clamp = 0;
    DisplayTransform display;  // exposure and tone curve of 8-bit images (PNG, the preview), not of the film
};

}  // namespace glint
