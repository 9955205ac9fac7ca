#pragma once

#include "glint/light/light.hpp"

namespace glint {

// Point light {type: point, position: [x, y, z], intensity: I}: radiant intensity I in every direction;
// a surface at distance r receives irradiance I cos θ / r². Casts hard shadows only (errata §7).
class PointLight final : public Light {
  public:
    PointLight(const Vec3& position, const Rgb& intensity) : position_(position), intensity_(intensity) {}
    std::optional<LightSample> sample(const Hit& at, Point2 u) const override;

    static std::unique_ptr<Light> create(Params& params, const BuildContext& context);

  private:
    Vec3 position_;
    Rgb intensity_;
};

}  // namespace glint
