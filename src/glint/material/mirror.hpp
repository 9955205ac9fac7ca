#pragma once

#include <memory>

#include "glint/material/material.hpp"
#include "glint/texture/texture.hpp"

namespace glint {

// Perfect specular reflection (paper eq. 16): wi = 2(wo·N)N − wo, reflecting a fraction kr of the
// light, on both sides. A delta lobe: evaluate() and pdf() are 0, sample() returns f = kr/|cos θi| and
// pdf 1, so the path weight is kr. Looks up kr into MaterialPoint::specular.
class Mirror final : public Material {
  public:
    explicit Mirror(std::shared_ptr<const Texture> reflectance) : reflectance_(std::move(reflectance)) {}

    static std::unique_ptr<Material> create(Params& params, const BuildContext& context);

  protected:
    MaterialPoint look_up(const Hit& hit) const override { return {{}, reflectance_->evaluate(hit)}; }
    Rgb evaluate(const MaterialPoint&, const Vec3&, const Vec3&) const override { return {}; }
    std::optional<BsdfSample> sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const override;
    double pdf(const MaterialPoint&, const Vec3&, const Vec3&) const override { return 0; }

  private:
    std::shared_ptr<const Texture> reflectance_;
};

}  // namespace glint
