#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "glint/texture/texture.hpp"

namespace glint {

// Ken Perlin's improved gradient noise ("Improving Noise", SIGGRAPH 2002): quintic fade, gradients
// from the 12 cube-edge directions chosen by a hashed lattice. Zero at every lattice point, within
// [−1, 1] everywhere. The permutation is made from `seed` by a hash, so noise is deterministic.
class PerlinNoise {
  public:
    explicit PerlinNoise(std::uint32_t seed = 0);
    double noise(const Vec3& p) const;
    // Σ_{i < octaves} |noise(2^i p)| / 2^i: Perlin's turbulence, in [0, 2).
    double turbulence(const Vec3& p, int octaves) const;

  private:
    std::array<std::uint8_t, 512> perm_{};  // a permutation of 0 … 255, repeated so indices need no wrap
};

// Noise {type: noise, scale, octaves, color_a, color_b}: a blend from color_a to color_b by the
// turbulence (clamped to 1) of the solid noise at scale · hit.point.
class NoiseTexture final : public Texture {
  public:
    NoiseTexture(double scale, int octaves, const Rgb& color_a, const Rgb& color_b)
        : scale_(scale), octaves_(octaves), a_(color_a), b_(color_b) {}
    Rgb evaluate(const Hit& hit) const override;
    double min_value() const override;
    double max_value() const override;

    static std::shared_ptr<const Texture> create(Params& params, const BuildContext& context);

  private:
    PerlinNoise noise_;
    double scale_;
    int octaves_;
    Rgb a_, b_;
};

}  // namespace glint
