#pragma once

#include "glint/light/light.hpp"

namespace glint {

// Ambient light {type: ambient, radiance: L}: a uniform radiance reaching every point from every
// direction, unoccluded (Suffern's ambient term). A matte surface of albedo ρ reflects ρ·L.
class AmbientLight final : public Light {
  public:
    explicit AmbientLight(const Rgb& radiance) : radiance_(radiance) {}
    std::optional<LightSample> sample(const Hit&, Point2) const override { return std::nullopt; }
    Rgb ambient() const override { return radiance_; }

    static std::unique_ptr<Light> create(Params& params, const BuildContext& context);

  private:
    Rgb radiance_;
};

}  // namespace glint
