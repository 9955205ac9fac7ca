#pragma once

#include <memory>

#include "glint/material/material.hpp"
#include "glint/texture/texture.hpp"

namespace glint {

// Lambertian diffuse: f = ρ/π (errata to paper eq. 15), on both sides of the surface. Looks up ρ into
// MaterialPoint::diffuse.
class Matte final : public Material {
  public:
    explicit Matte(std::shared_ptr<const Texture> albedo);
    explicit Matte(const Rgb& albedo) : Matte(std::make_shared<ConstantTexture>(albedo)) {}

    static std::unique_ptr<Material> create(Params& params, const BuildContext& context);

  protected:
    MaterialPoint look_up(const Hit& hit) const override { return {albedo_->evaluate(hit), {}}; }
    Rgb evaluate(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const override;
    std::optional<BsdfSample> sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const override;
    double pdf(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const override;
    Rgb ambient_reflectance(const MaterialPoint& point) const override { return point.diffuse; }

  private:
    std::shared_ptr<const Texture> albedo_;
};

}  // namespace glint
