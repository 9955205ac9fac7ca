#pragma once

#include "glint/sampling/sampler.hpp"

namespace glint {

// Multi-jittered sampling (paper §3.2, figure 6; Chiu, Shirley & Wang 1994) in Kensler's correlated
// form ("Correlated Multi-Jittered Sampling", Pixar 2013): jittered on a coarse m × r grid (one point
// per cell) and n-rooks on the fine n × n grid (one point per row and column), n = m·r. The pattern is
// built on the fly from hash permutations chosen per pixel and dimension: no tables.
//
// Any n works and is taken as is: the coarse grid is the most nearly square factorisation m × r of n
// (m the largest divisor ≤ √n), so a square n gets the paper's √n × √n grid, 8 gets 2 × 4, and a prime
// n degenerates to 1 × n (n-rooks with a 1-D jitter). The n-rooks condition always holds.
class MultiJitteredSampler final : public Sampler {
  public:
    explicit MultiJitteredSampler(std::uint32_t samples_per_pixel);
    std::uint32_t samples_per_pixel() const override { return columns_ * rows_; }
    std::uint32_t columns() const { return columns_; }  // m
    std::uint32_t rows() const { return rows_; }        // r
    Point2 sample_2d(const SampleHashes& key, std::uint32_t dimension) const override;

  private:
    std::uint32_t columns_, rows_;
};

}  // namespace glint
