// AOVs (arbitrary output variables): what a denoiser or a compositor needs beside the radiance —
// `glint render --aov albedo,normal,depth,spp,variance`.
//
// albedo, normal and depth come from the camera rays of the render's own samples (the same film and
// lens positions, render_sample's camera_ray), averaged over the first min(spp, kMaxAovSamples) samples
// of each pixel, so that they are antialiased and defocused as the image is:
// - albedo (R, G, B): the reflectance of the first surface that is not perfectly specular, its
//   diffuse plus its specular reflectance (MaterialPoint; clamped to 1): matte's colour, a rough
//   metal's F₀, principled's base colour. Perfect mirrors, smooth metals and smooth glass are followed
//   (the lobe their BSDF samples; at most kMaxSpecularBounces), as denoisers expect. 0 where the ray
//   escapes (the sky) or meets only an emitter.
// - normal (X, Y, Z): the shading normal of that same surface in world space, turned to face the ray
//   (so a denoiser sees the side it looks at); 0 where the ray escapes. Averages of unit vectors: shorter
//   than 1 where a pixel straddles an edge.
// - depth (Z): the distance from the camera to the first surface the camera ray meets (a mirror
//   itself, not what it shows), along the ray, in scene units; the mean over the samples that hit
//   something, +∞ where none does.
// And from the film, exactly:
// - spp (Y): the samples in the pixel's mean (fewer than asked where samples were NaN or infinite).
// - variance (Y): the variance of the pixel's mean luminance as an estimate (Film::mean_variance): where
//   more samples would pay.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "glint/image/film.hpp"
#include "glint/image/image.hpp"
#include "glint/render/view.hpp"
#include "glint/world/settings.hpp"
#include "glint/world/world.hpp"

namespace glint {

inline constexpr std::uint32_t kMaxAovSamples = 64;
inline constexpr int kMaxSpecularBounces = 8;

struct AovRequest {
    bool albedo = false, normal = false, depth = false, spp = false, variance = false;
    bool any() const { return albedo || normal || depth || spp || variance; }
};

// The names of the AOVs, in the order they are written: albedo, normal, depth, spp, variance.
const std::vector<std::string>& aov_names();

// "albedo,normal" → the request. Throws std::invalid_argument whose message names an unknown AOV with a
// did-you-mean and the list.
AovRequest parse_aov_list(const std::string& list);

// The requested layers over `window` (the rendered pixels; the image written has its size), after the
// render: `film` holds its samples, `samples_per_pixel` is how many each pixel took. Deterministic:
// a pure function of the world, the view, the film and the window, whatever the threads.
std::vector<ImageLayer> render_aovs(const World& world, const View& view, const Film& film,
                                    const PixelWindow& window, std::uint32_t samples_per_pixel,
                                    const AovRequest& request);

}  // namespace glint
