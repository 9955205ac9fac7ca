#pragma once

#include "glint/light/light.hpp"

namespace glint {

// Directional light {type: directional, direction: [x, y, z], irradiance: E}: parallel light from
// infinitely far away (the sun), travelling along `direction`. A surface facing it at angle θ receives
// irradiance E cos θ, whatever its position; shadows are hard.
class DirectionalLight final : public Light {
  public:
    DirectionalLight(const Vec3& direction, const Rgb& irradiance)
        : to_light_(-normalize(direction)), irradiance_(irradiance) {}
    std::optional<LightSample> sample(const Hit& at, Point2 u) const override;

    static std::unique_ptr<Light> create(Params& params, const BuildContext& context);

  private:
    Vec3 to_light_;  // unit, from the scene towards the light
    Rgb irradiance_;
};

}  // namespace glint
