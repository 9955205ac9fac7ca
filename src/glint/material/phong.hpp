#pragma once

#include <memory>

#include "glint/material/material.hpp"
#include "glint/texture/texture.hpp"

namespace glint {

// Normalised (energy-conserving) Phong, two-sided:
//   f = kd/π + ks · (n + 2)/(2π) · cosⁿα,  α the angle between wi and the mirror direction of wo.
// The (n + 2)/(2π) factor makes the lobe reflect at most ks, so kd + ks ≤ 1 conserves energy
// (Lafortune & Willems 1994). Sampling mixes a cosine-weighted direction (probability ∝ lum(kd)) with
// a direction from the lobe cosⁿα about the mirror direction (∝ lum(ks)); pdf is the mixture density.
// Looks up kd into MaterialPoint::diffuse and ks into MaterialPoint::specular.
class Phong final : public Material {
  public:
    Phong(std::shared_ptr<const Texture> diffuse, std::shared_ptr<const Texture> specular, double exponent)
        : diffuse_(std::move(diffuse)), specular_(std::move(specular)), exponent_(exponent) {}

    static std::unique_ptr<Material> create(Params& params, const BuildContext& context);

  protected:
    MaterialPoint look_up(const Hit& hit) const override {
        return {diffuse_->evaluate(hit), specular_->evaluate(hit)};
    }
    Rgb evaluate(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const override;
    std::optional<BsdfSample> sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const override;
    double pdf(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const override;
    Rgb ambient_reflectance(const MaterialPoint& point) const override { return point.diffuse; }

  private:
    std::shared_ptr<const Texture> diffuse_, specular_;
    double exponent_;
};

}  // namespace glint
