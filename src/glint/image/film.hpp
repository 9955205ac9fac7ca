#pragma once

#include <cstdint>
#include <vector>

#include "glint/core/color.hpp"
#include "glint/image/image.hpp"

namespace glint {

// Accumulates radiance samples per pixel (a box filter: each sample counts for the pixel it lies in).
// Sums are in double, and each pixel is only ever written by the tile that owns it, in sample order,
// so the result does not depend on threads or tiling.
class Film {
  public:
    Film(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }

    void add_sample(int x, int y, const Rgb& radiance) {
        Pixel& p = pixels_[static_cast<size_t>(y) * width_ + x];
        p.sum += radiance;
        const double luminance = radiance.luminance();
        p.luminance_squares += luminance * luminance;
        p.count += 1;
    }
    // The mean of the samples of a pixel (black before any).
    Rgb pixel(int x, int y) const;
    std::uint64_t sample_count(int x, int y) const {
        return pixels_[static_cast<size_t>(y) * width_ + x].count;
    }
    void clear();
    Image to_image() const;
    // The pixels x0 ≤ x < x0 + width, y0 ≤ y < y0 + height alone (a crop, a band), as to_image gives them.
    Image to_image(int x0, int y0, int width, int height) const;

    // What a pixel holds: the sum of its samples and how many. Read and restored whole by checkpoints
    // (render/checkpoint.hpp), so that a resumed render adds to exactly the sums it left.
    struct Pixel {
        Rgb sum;
        double luminance_squares = 0;  // Σ Y² of the samples: their variance (the `variance` AOV)
        std::uint64_t count = 0;
    };
    // The variance of the pixel's mean luminance as an estimate: the samples' unbiased variance of Y over
    // their count, (Σ Y² − (Σ Y)² / n) / (n (n − 1)); 0 with fewer than two samples.
    double mean_variance(int x, int y) const;
    const Pixel& raw_pixel(int x, int y) const { return pixels_[static_cast<size_t>(y) * width_ + x]; }
    void set_raw_pixel(int x, int y, const Pixel& pixel) {
        pixels_[static_cast<size_t>(y) * width_ + x] = pixel;
    }

  private:
    int width_;
    int height_;
    std::vector<Pixel> pixels_;
};

}  // namespace glint
