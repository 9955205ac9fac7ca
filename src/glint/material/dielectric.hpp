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
// `fresnel` may replace F by Schlick's approximation R₀ + (1 − R₀)(1 − cos θ)⁵, R₀ = ((n₁ − n₂)/(n₁ + n₂))²:
//   Schlick:        θ the angle of wo on its own side, also from inside the glass (Ray Tracing in One
//                   Weekend's dielectric);
//   SchlickOutside: θ the angle on the outside (index 1): wo's from outside, the refracted direction's
//                   from inside (smallpt's glass).
// Either way the ray reflects whenever Snell's law has no refraction.
// Inside, light is absorbed by Beer's law with coefficient `absorption` σ (see Material::absorption).
class Dielectric final : public Material {
  public:
    enum class Fresnel { Exact, Schlick, SchlickOutside };
    Dielectric(double ior, const Rgb& absorption, Fresnel fresnel = Fresnel::Exact)
        : ior_(ior), absorption_(absorption), fresnel_(fresnel) {}
    Rgb absorption() const override { return absorption_; }

    static std::unique_ptr<Material> create(Params& params, const BuildContext& context);

  protected:
    Rgb evaluate(const MaterialPoint&, const Vec3&, const Vec3&) const override { return {}; }
    std::optional<BsdfSample> sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const override;
    double pdf(const MaterialPoint&, const Vec3&, const Vec3&) const override { return 0; }

  private:
    double ior_;
    Rgb absorption_;
    Fresnel fresnel_;
};

}  // namespace glint
