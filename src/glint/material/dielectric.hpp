#pragma once

#include <memory>

#include "glint/material/material.hpp"

namespace glint {

// Smooth dielectric (glass, water, diamond) of index `ior` inside and 1 outside (paper §VIII with the
// errata). hit.normal points outside; wo may be on either side. sample() reflects with probability
// F, the exact dielectric Fresnel reflectance, and otherwise refracts by Snell's law (η = n₁/n₂ from
// wo's side to the other); under total internal reflection F = 1. Both lobes are delta:
//   reflection:    f = F / |cos θi|,                  pdf = F      (path weight 1)
//   transmission:  f = (1 − F) (n₁/n₂)² / |cos θi|,   pdf = 1 − F  (path weight (n₁/n₂)²)
// glint transports radiance, and radiance changes across an interface: L is proportional to n² for
// the same flux, so a camera path crossing from index n₁ into n₂ carries (n₁/n₂)². The factors
// cancel on a path that enters and leaves the same medium.
// With `schlick_fresnel`, F is instead Schlick's R₀ + (1 − R₀)(1 − cos θ)⁵, R₀ = ((n₁ − n₂)/(n₁ + n₂))²,
// with θ the angle of wo on its own side, as in Ray Tracing in One Weekend's dielectric (which takes
// that cosine even from inside the glass, and reflects whenever Snell's law has no refraction).
// Inside, light is absorbed by Beer's law with coefficient `absorption` σ (see Material::absorption).
class Dielectric final : public Material {
  public:
    Dielectric(double ior, const Rgb& absorption, bool schlick_fresnel = false)
        : ior_(ior), absorption_(absorption), schlick_fresnel_(schlick_fresnel) {}
    Rgb evaluate(const Hit&, const Vec3&, const Vec3&) const override { return {}; }
    std::optional<BsdfSample> sample(const Hit& hit, const Vec3& wo, Point2 u) const override;
    double pdf(const Hit&, const Vec3&, const Vec3&) const override { return 0; }
    Rgb absorption() const override { return absorption_; }

    static std::unique_ptr<Material> create(Params& params, const BuildContext& context);

  private:
    double ior_;
    Rgb absorption_;
    bool schlick_fresnel_;  // Schlick's approximation instead of the exact Fresnel reflectance
};

}  // namespace glint
