#pragma once

#include "glint/sampling/sampler.hpp"

namespace glint {

// Jittered (stratified) sampling, paper §2.3: the pixel is cut into a k × k grid and one random point
// is placed in each cell. A request for n samples is rounded up to the next square k² ≥ n.
class JitteredSampler final : public Sampler {
  public:
    explicit JitteredSampler(std::uint32_t samples_per_pixel);
    std::uint32_t samples_per_pixel() const override { return grid_ * grid_; }
    std::uint32_t grid_size() const { return grid_; }
    Point2 sample_2d(const SampleHashes& key, std::uint32_t dimension) const override;
    // Jittered in 1-D over all k² intervals (the x of the 2-D pattern has only k strata).
    double sample_1d(const SampleHashes& key, std::uint32_t dimension) const override;

  private:
    std::uint32_t grid_;    // k
    double inverse_grid_;   // 1/k
    double inverse_count_;  // 1/k²
};

}  // namespace glint
