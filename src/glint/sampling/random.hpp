#pragma once

#include "glint/sampling/sampler.hpp"

namespace glint {

class RandomSampler final : public Sampler {
  public:
    explicit RandomSampler(std::uint32_t samples_per_pixel) : Sampler(0), spp_(samples_per_pixel) {}
    std::uint32_t samples_per_pixel() const override { return spp_; }
    bool extendable() const override { return true; }
    Point2 sample_2d(const SampleHashes& key, std::uint32_t dimension) const override;

  private:
    std::uint32_t spp_;
};

}  // namespace glint
