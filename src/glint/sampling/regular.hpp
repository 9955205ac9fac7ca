#pragma once

#include "glint/sampling/sampler.hpp"

namespace glint {

// Regular sampling (paper §2.1, figure 3): the centres of a k × k grid of cells. A request for n samples
// is rounded up to the next square k² ≥ n, as for jittered. Every pixel gets the same point set, which
// is what makes regular sampling alias; only the order in which sample indices visit the cells is
// shuffled per pixel and dimension, so the film and lens positions of one sample are not correlated.
class RegularSampler final : public Sampler {
  public:
    explicit RegularSampler(std::uint32_t samples_per_pixel);
    std::uint32_t samples_per_pixel() const override { return grid_ * grid_; }
    std::uint32_t grid_size() const { return grid_; }
    Point2 sample_2d(const SampleHashes& key, std::uint32_t dimension) const override;
    // The centres of n = k² equal intervals: regular in 1-D too.
    double sample_1d(const SampleHashes& key, std::uint32_t dimension) const override;

  private:
    std::uint32_t grid_;  // k
};

// k = ⌈√n⌉ (at least 1), computed without trusting floating-point sqrt on perfect squares.
std::uint32_t square_grid_size(std::uint32_t samples_per_pixel);

}  // namespace glint
