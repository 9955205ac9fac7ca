#pragma once

#include "glint/sampling/sampler.hpp"

namespace glint {

// n-rooks sampling (paper §3.1, figure 5; a Latin hypercube): n points in an n × n grid with exactly
// one in each row and each column, at a random place inside its cell. Any n works: nothing is rounded.
// The rows and columns are matched by two hash permutations chosen per pixel and dimension. The 1-D
// projections are perfectly stratified; the 2-D distribution is no better than random (errata §3.1).
class NRooksSampler final : public Sampler {
  public:
    explicit NRooksSampler(std::uint32_t samples_per_pixel) : n_(std::max(1u, samples_per_pixel)) {}
    std::uint32_t samples_per_pixel() const override { return n_; }
    Point2 sample_2d(const SampleHashes& key, std::uint32_t dimension) const override;

  private:
    std::uint32_t n_;
};

}  // namespace glint
