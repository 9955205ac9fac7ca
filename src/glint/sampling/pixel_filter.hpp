// Pixel filters by importance sampling, as pbrt-v4 does: the film sample u ∈ [0,1)² is warped to a
// position drawn from the filter's density around the pixel, and every sample weighs 1. A sample still
// counts only towards its own pixel (no splatting into neighbours), so tiles and determinism are as
// with boxes; what changes is which rays a pixel averages: its footprint is the filter instead of the
// pixel's square.
//
// - `box`: the pixel's square, the offset is u itself (the images are those of glint without filters).
// - `tent`: per axis (separably) a triangle of half-width `radius` pixels around the centre, pbrt's
//   triangle filter. With `subpixels` s > 1 the pixel is split into s × s sub-pixels, one picked by the
//   leading part of u (u·s rounded down) and a tent centred on it warps the rest, (u·s mod 1): the
//   footprint per axis is the mean of s tents. smallpt's is {radius: 0.5, subpixels: 2}, a trapezoid
//   over [−0.25, 1.25]. Every stratum of u stays a compact interval of one sub-pixel's tent, so a
//   stratified pattern stays stratified.
#pragma once

#include <string>

#include "glint/core/vec.hpp"
#include "glint/params/name_table.hpp"

namespace glint {

enum class PixelFilterType { box, tent };

// The words a scene writes for the filter types.
const EnumTable<PixelFilterType>& pixel_filter_types();

// The limit of `subpixels`: far past any use (smallpt takes 2), and the sub-pixel index takes no more
// than 10 of the sample's bits, which keep 32 or more.
inline constexpr int kMaxSubpixels = 1024;

struct PixelFilter {
    PixelFilterType type = PixelFilterType::box;
    double radius = 1;  // tent: half-width per axis, in pixels
    int subpixels = 1;  // tent: sub-pixels per side, each with its own tent about its centre

    // The film position relative to the pixel's corner, in pixels, for the film sample u ∈ [0,1)²:
    // u itself for a box; the pixel's (or a sub-pixel's) centre plus the tent's warp otherwise. Its
    // mean over u is the pixel's centre (½, ½) for every filter.
    Point2 offset(Point2 u) const;

    friend bool operator==(const PixelFilter&, const PixelFilter&) = default;
};

// The filter of `render.filter` (a map {type: NAME, …}, after typed_object turned a plain word into
// one): `type` from pixel_filter_types(); a tent reads `radius` (> 0, default 1) and `subpixels`
// (1 … kMaxSubpixels, default 1). A box reads no key. Does not call finish().
PixelFilter read_pixel_filter(Params& params);

// The warp of one axis of a tent filter: v ∈ [0,1) → t ∈ [−1,1], distributed with the density
// 1 − |t|. Its inverse CDF: √(2v) − 1 below ½, 1 − √(2 − 2v) above (smallpt's dx with r = 2v).
double tent_inverse_cdf(double v);

}  // namespace glint
