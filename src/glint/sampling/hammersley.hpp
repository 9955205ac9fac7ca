#pragma once

#include "glint/sampling/sampler.hpp"

namespace glint {

// The unscrambled Hammersley point i of n: (i / n, Φ₂(i)) (paper §3.3, eq. 1 as corrected by the errata).
Point2 hammersley_point(std::uint32_t i, std::uint32_t n);

// Hammersley sampling (paper §3.3, figure 7): the n points (i/n, Φ₂(i)), randomised per pixel and
// dimension so that neighbouring pixels do not repeat one pattern (which would alias):
//   x: a Cranley–Patterson rotation by a random multiple of 1/n plus a random offset inside the stratum,
//      so the x values stay one per interval [k/n, (k+1)/n);
//   y: a random XOR of the binary digits of Φ₂(i) (a random digit scramble), which keeps the strata
//      of Φ₂ and fills the digits below 1/n with random bits.
// For n = 2^k the scrambled set is still a (0, k, 2)-net, like the plain one. Any n works and is taken
// as is (y is best stratified when n is a power of two). Which point a sample index gets is shuffled
// per pixel and dimension, so that the film and lens positions of one sample are not correlated.
class HammersleySampler final : public Sampler {
  public:
    explicit HammersleySampler(std::uint32_t samples_per_pixel) : n_(std::max(1u, samples_per_pixel)) {}
    std::uint32_t samples_per_pixel() const override { return n_; }
    Point2 sample_2d(const SampleHashes& key, std::uint32_t dimension) const override;

  private:
    std::uint32_t n_;
};

}  // namespace glint
