#pragma once

#include <memory>

#include "glint/material/material.hpp"
#include "glint/material/microfacet.hpp"
#include "glint/texture/texture.hpp"

namespace glint {

// Rough metal (glossy reflector), two-sided: a GGX (Trowbridge–Reitz) microfacet BRDF (microfacet.hpp),
//   f = F(wo·h) D(h) G(wo, wi) / (4 cos θo cos θi),  h = (wo + wi)/‖wo + wi‖,
// with the height-correlated Smith shadowing G = 1/(1 + Λ(wo) + Λ(wi)) and Schlick's Fresnel with the
// metal's colour as the reflectance at normal incidence F₀. Width α = roughness². Sampled by the
// distribution of visible normals (Heitz 2018), pdf = G₁(wo) D(h) / (4 cos θo); a sampled direction
// below the surface is rejected (sample() returns nullopt), so the sampling density is exactly pdf().
// Below roughness 0.03 (α < GgxDistribution::kMinAlpha = 10⁻³) the lobe is a perfect mirror of
// reflectance F(θo): a delta lobe. Single scattering only: very rough metal loses the light that bounces
// between microfacets.
// Looks up F₀ into MaterialPoint::specular.
class Metal final : public Material {
  public:
    Metal(std::shared_ptr<const Texture> reflectance, double roughness)
        : reflectance_(std::move(reflectance)), ggx_(roughness * roughness) {}
    bool is_mirror() const { return ggx_.alpha() < GgxDistribution::kMinAlpha; }

    static std::unique_ptr<Material> create(Params& params, const BuildContext& context);

  protected:
    MaterialPoint look_up(const Hit& hit) const override { return {{}, reflectance_->evaluate(hit)}; }
    Rgb evaluate(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const override;
    std::optional<BsdfSample> sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const override;
    double pdf(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const override;

  private:
    std::shared_ptr<const Texture> reflectance_;
    GgxDistribution ggx_;
};

}  // namespace glint
