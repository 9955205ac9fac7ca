#pragma once

#include <memory>

#include "glint/material/material.hpp"
#include "glint/texture/texture.hpp"

namespace glint {

// glTF 2.0's metallic-roughness material (the spec's Appendix B), two-sided: a blend by `metallic` m of
// a metal and a dielectric that share one GGX specular lobe of width α = roughness² (microfacet.hpp:
// height-correlated Smith G, no multiple scattering),
//   f = (1 − m) · dielectric + m · metal,
//   metal      = Schlick(wo·h; F₀ = base colour) · S,
//   dielectric = s F(wo·h) · S  +  base colour/π · (1 − s F(θo)) · (1 − s F(θi)),
// with S = D(h) G(wo, wi) / (4 cos θo cos θi) the lobe without Fresnel, F the exact dielectric Fresnel
// reflectance of index `ior` (F₀ = ((ior − 1)/(ior + 1))², 0.04 for 1.5) and s the `specular` scale.
// The Lambertian base keeps what the specular layer does not reflect. glTF's fresnel_mix weights it by
// 1 − F(wo·h) instead; that is not energy-conserving (a smooth white dielectric seen at grazing angles
// reflects F(θo) ≈ 0.4 specularly while its base still reflects about 0.9), so glint weights it as
// plastic does, by the Fresnel transmittance into and out of the layer, which keeps every albedo ≤ 1.
// At ior 1 (F = 0) the dielectric is exactly Lambertian.
//
// α is at least GgxDistribution::kMinAlpha, so there is no delta lobe even at roughness 0 (a textured
// roughness needs no second code path). sample() picks the specular lobe (visible normals) or the
// base (cosine-weighted) in proportion to their estimated weights at θo; pdf() is the mixture's density.
//
// Looks up diffuse = (1 − m) · base colour (the base's albedo), specular = m · base colour (the metal's
// share of F₀), metallic = m and alpha.
class Principled final : public Material {
  public:
    Principled(std::shared_ptr<const Texture> base_color, std::shared_ptr<const Texture> metallic,
               std::shared_ptr<const Texture> roughness, double ior, double specular);

    static std::unique_ptr<Material> create(Params& params, const BuildContext& context);

  protected:
    MaterialPoint look_up(const Hit& hit) const override;
    Rgb evaluate(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const override;
    std::optional<BsdfSample> sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const override;
    double pdf(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const override;
    // The reflectance at normal incidence: the mixed F₀ = m · base colour + (1 − m) s F₀ of the specular
    // lobe, plus the base through the layer, (1 − s F₀)² (1 − m) · base colour (as plastic's).
    Rgb ambient_reflectance(const MaterialPoint& point) const override;

  private:
    // s F(θ): the dielectric layer's reflectance at cosine `cos_theta` from either side.
    double dielectric_reflectance(double cos_theta) const;
    double specular_probability(const MaterialPoint& point, const Vec3& wo) const;

    std::shared_ptr<const Texture> base_color_;
    std::shared_ptr<const Texture> metallic_;
    std::shared_ptr<const Texture> roughness_;
    double ior_;
    double specular_;
};

}  // namespace glint
