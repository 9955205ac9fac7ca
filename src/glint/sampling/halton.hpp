#pragma once

#include "glint/sampling/sampler.hpp"

namespace glint {

// Halton sampling (beyond the paper): point i is (Φ₂(i), Φ₃(i)), i = 0 … n−1, Owen-scrambled per
// pixel and dimension (a nested random permutation of the digits in each base, chosen by a hash of the
// digits above), which keeps every stratification of the plain sequence: the first 2^a·3^b points have
// one point in each cell of a 2^a × 3^b grid. Any n works and is taken as is. Every 2-D dimension uses
// bases 2 and 3 with its own scramble, and the order of the points is shuffled per pixel and dimension,
// so dimensions are not correlated (and high bases, which stratify badly at small n, are never used).
class HaltonSampler final : public Sampler {
  public:
    explicit HaltonSampler(std::uint32_t samples_per_pixel);
    std::uint32_t samples_per_pixel() const override { return n_; }
    Point2 sample_2d(const SampleHashes& key, std::uint32_t dimension) const override;

  private:
    std::uint32_t n_;
    std::uint32_t digits3_;  // base-3 digits of n − 1: the ones the strata of n points depend on
};

// Φ₃(i) under the nested digit scramble chosen by `seed` (seed 0 is a scramble too, not the identity).
// The first `scrambled_digits` digits are permuted one by one; below them the point is placed uniformly
// at random, which is what permuting every lower digit at random amounts to. A pattern of n points
// needs only the digits of n − 1 to keep its strata.
double owen_scrambled_radical_inverse3(std::uint32_t i, std::uint64_t seed,
                                       std::uint32_t scrambled_digits = 21);

}  // namespace glint
