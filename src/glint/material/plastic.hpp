#pragma once

#include <memory>

#include "glint/material/material.hpp"
#include "glint/texture/texture.hpp"

namespace glint {

// Smooth plastic: a Lambertian base of albedo ρ under a smooth dielectric coat of index `ior`, two-sided.
//   coat:  a delta mirror lobe of reflectance F(θo), the exact dielectric Fresnel reflectance;
//   base:  f = ρ/π · (1 − F(θi)) · (1 − F(θo)): light enters the coat (1 − F), is scattered by the base
//          and leaves through the coat (1 − F) again.
// Light reflected back down by the underside of the coat is ignored, so a white plastic reflects a
// little less than all the light (the model is energy-conserving and reciprocal, not energy-preserving).
// sample() picks the coat with probability F / (F + (1 − F)·mean(ρ)), the ratio of the lobes' weights.
// Looks up ρ into MaterialPoint::diffuse.
class Plastic final : public Material {
  public:
    Plastic(std::shared_ptr<const Texture> diffuse, double ior) : diffuse_(std::move(diffuse)), ior_(ior) {}

    static std::unique_ptr<Material> create(Params& params, const BuildContext& context);

  protected:
    MaterialPoint look_up(const Hit& hit) const override { return {diffuse_->evaluate(hit), {}}; }
    Rgb evaluate(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const override;
    std::optional<BsdfSample> sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const override;
    double pdf(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const override;
    // The ambient term at normal incidence: R₀ + (1 − R₀)² ρ.
    Rgb ambient_reflectance(const MaterialPoint& point) const override;

  private:
    double coat_reflectance(const Vec3& w) const;
    double coat_probability(const MaterialPoint& point, const Vec3& wo) const;

    std::shared_ptr<const Texture> diffuse_;
    double ior_;
};

}  // namespace glint
