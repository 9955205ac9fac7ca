#pragma once

#include "glint/sampling/sampler.hpp"

namespace glint {

// Owen-scrambled Sobol sampling (beyond the paper; Burley, "Practical Hash-based Owen Scrambling",
// JCGT 2020): the first two Sobol dimensions, each Owen-scrambled by a hash with its own seed per pixel
// and 2-D dimension, and the sample index shuffled by the same kind of hash. The shuffle maps indices
// 0 … 2^k−1 onto one aligned block of 2^k Sobol points, so for n = 2^k every pixel gets a (0, k, 2)-net:
// one point in each elementary interval of area 1/n (in particular one per cell of the √n × √n grid
// when k is even, and perfect 1-D strata). Any n works and is taken as is; the guarantees are at
// powers of two.
class SobolSampler final : public Sampler {
  public:
    explicit SobolSampler(std::uint32_t samples_per_pixel) : n_(std::max(1u, samples_per_pixel)) {}
    std::uint32_t samples_per_pixel() const override { return n_; }
    bool extendable() const override { return true; }  // the index is only scrambled, never wrapped
    Point2 sample_2d(const SampleHashes& key, std::uint32_t dimension) const override;
    // The x of sample_2d, without computing its y.
    double sample_1d(const SampleHashes& key, std::uint32_t dimension) const override;

  private:
    std::uint32_t n_;
};

}  // namespace glint
