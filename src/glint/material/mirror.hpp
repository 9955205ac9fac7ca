#pragma once

#include <memory>

#include "glint/material/material.hpp"
#include "glint/texture/texture.hpp"

namespace glint {

// Perfect specular reflection (paper eq. 16): wi = 2(wo·N)N − wo, reflecting a fraction kr of the
// light, on both sides. A delta lobe: evaluate() and pdf() are 0, sample() returns f = kr/|cos θi| and
// pdf 1, so the path weight is kr.
class Mirror final : public Material {
  public:
    explicit Mirror(std::shared_ptr<const Texture> reflectance) : reflectance_(std::move(reflectance)) {}
    Rgb evaluate(const Hit&, const Vec3&, const Vec3&) const override { return {}; }
    std::optional<BsdfSample> sample(const Hit& hit, const Vec3& wo, Point2 u) const override;
    double pdf(const Hit&, const Vec3&, const Vec3&) const override { return 0; }

    static std::unique_ptr<Material> create(Params& params, const BuildContext& context);

  private:
    std::shared_ptr<const Texture> reflectance_;
};

// The mirror direction of wo about the shading normal (either side): R = 2(wo·N)N − wo.
inline Vec3 mirror_direction(const Hit& hit, const Vec3& wo) {
    return 2 * dot(wo, hit.shading_normal) * hit.shading_normal - wo;
}

}  // namespace glint
