#pragma once

#include <memory>

#include "glint/material/material.hpp"
#include "glint/texture/texture.hpp"

namespace glint {

// A light-emitting surface that reflects nothing: L_e = radiance × scale towards wo. One-sided by
// default: it emits only to the side hit.normal points to (outwards on closed shapes), so a lamp's
// inside stays dark; `two_sided` emits to both sides.
class Emissive final : public Material {
  public:
    Emissive(std::shared_ptr<const Texture> radiance, double scale, bool two_sided)
        : radiance_(std::move(radiance)), scale_(scale), two_sided_(two_sided) {}
    Rgb emitted(const Hit& hit, const Vec3& wo) const override;

    static std::unique_ptr<Material> create(Params& params, const BuildContext& context);

  protected:
    Rgb evaluate(const MaterialPoint&, const Vec3&, const Vec3&) const override { return {}; }
    std::optional<BsdfSample> sample(const MaterialPoint&, const Vec3&, Point2) const override {
        return std::nullopt;
    }
    double pdf(const MaterialPoint&, const Vec3&, const Vec3&) const override { return 0; }

  private:
    std::shared_ptr<const Texture> radiance_;
    double scale_;
    bool two_sided_;
};

}  // namespace glint
