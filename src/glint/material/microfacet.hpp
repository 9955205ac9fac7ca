// The GGX (Trowbridge–Reitz) microfacet distribution, shared by the materials with a rough specular
// reflection lobe (metal, principled), so that they agree on one D, one G and one sampling routine.
#pragma once

#include <cmath>

#include "glint/core/vec.hpp"

namespace glint {

// Isotropic GGX of width α in the shading frame (z the shading normal), for reflection on either side of
// the surface: every function takes wo and wi on the same side and uses |z| as their cosines.
//   D(h)       = α² / (π (cos²θh (α² − 1) + 1)²)
//   Λ(θ)       = (√(1 + α² tan²θ) − 1) / 2, the Smith masking function;
//   G(wo, wi)  = 1 / (1 + Λ(wo) + Λ(wi)), the height-correlated Smith masking-shadowing;
//   G₁(wo)     = 1 / (1 + Λ(wo)).
// Single scattering only: light that bounces between microfacets is lost, which darkens rough surfaces
// (a white lobe reflects 99 % at α = 0.09 but only 1 − ln 2 ≈ 31 % at α = 1, at normal incidence).
class GgxDistribution {
  public:
    // Below this width the lobe is too narrow to evaluate or sample reliably: metal becomes a perfect
    // mirror there and principled clamps to it (α = 10⁻³ blurs by about a twentieth of a degree).
    static constexpr double kMinAlpha = 1e-3;

    explicit GgxDistribution(double alpha) : alpha_(alpha) {}
    double alpha() const { return alpha_; }

    // D(h) G(wo, wi) / (4 cos θo cos θi): the BRDF without its Fresnel factor, for wo and wi on the same
    // side and h = normalize(wo + wi).
    double reflection(const Vec3& wo, const Vec3& wi, const Vec3& h) const {
        const double cos_o = std::abs(wo.z), cos_i = std::abs(wi.z);
        const double g = 1 / (1 + lambda(cos_o) + lambda(cos_i));
        return distribution(std::abs(h.z)) * g / (4 * cos_o * cos_i);
    }

    // The solid-angle density of sample_reflection's wi, for wi on wo's side and h = normalize(wo + wi):
    // the visible normals' density G₁(wo) D(h) max(0, wo·h) / cos θo times the reflection's Jacobian
    // 1 / (4 wo·h), that is G₁(wo) D(h) / (4 cos θo).
    double reflection_pdf(const Vec3& wo, const Vec3& h) const {
        const double cos_o = std::abs(wo.z);
        return distribution(std::abs(h.z)) / ((1 + lambda(cos_o)) * 4 * cos_o);
    }

    // wo reflected about a microfacet normal drawn from the normals visible from wo (Heitz 2018, "Sampling
    // the GGX Distribution of Visible Normals"), on wo's side. The result may point below the surface (a
    // reflection off a steep facet): callers reject it, so that the density of what they return is exactly
    // reflection_pdf. wo must not lie in the surface (wo.z ≠ 0).
    Vec3 sample_reflection(const Vec3& wo, Point2 u) const;

  private:
    double distribution(double cos_h) const {
        const double a2 = alpha_ * alpha_;
        const double d = cos_h * cos_h * (a2 - 1) + 1;
        return a2 / (kPi * d * d);
    }
    double lambda(double cos_theta) const {
        const double c2 = cos_theta * cos_theta;
        const double tan2 = std::max(0.0, 1 - c2) / c2;
        return 0.5 * (std::sqrt(1 + alpha_ * alpha_ * tan2) - 1);
    }

    double alpha_;
};

}  // namespace glint
