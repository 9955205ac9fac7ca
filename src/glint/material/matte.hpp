#pragma once

#include "glint/material/material.hpp"

namespace glint {

// Lambertian diffuse: f = ρ/π (errata to paper eq. 15), on both sides of the surface.
class Matte final : public Material {
  public:
    explicit Matte(const Rgb& albedo) : albedo_(albedo) {}
    Rgb evaluate(const Hit& hit, const Vec3& wo, const Vec3& wi) const override;
    std::optional<BsdfSample> sample(const Hit& hit, const Vec3& wo, Point2 u) const override;
    double pdf(const Hit& hit, const Vec3& wo, const Vec3& wi) const override;
    Rgb ambient_reflectance(const Hit&) const override { return albedo_; }

    static std::unique_ptr<Material> create(Params& params, const BuildContext& context);

  private:
    Rgb albedo_;
};

}  // namespace glint
