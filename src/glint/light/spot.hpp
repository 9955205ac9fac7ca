#pragma once

#include "glint/light/light.hpp"

namespace glint {

// Spot light {type: spot, position, direction | look_at, intensity, angle, falloff_angle}: a point
// light whose intensity I is full inside the cone of half-angle `falloff_angle` around `direction`,
// zero outside the cone of half-angle `angle`, and falls off smoothly between them (smoothstep in
// cos θ, as pbrt-v4). Hard shadows.
class SpotLight final : public Light {
  public:
    SpotLight(const Vec3& position, const Vec3& direction, const Rgb& intensity, double cos_outer,
              double cos_inner)
        : position_(position),
          axis_(normalize(direction)),
          intensity_(intensity),
          cos_outer_(cos_outer),
          cos_inner_(cos_inner) {}
    std::optional<LightSample> sample(const Hit& at, Point2 u) const override;
    // The fraction of I sent at angle θ to the axis, given cos θ.
    double falloff(double cos_theta) const;

    static std::unique_ptr<Light> create(Params& params, const BuildContext& context);

  private:
    Vec3 position_;
    Vec3 axis_;
    Rgb intensity_;
    double cos_outer_, cos_inner_;
};

}  // namespace glint
