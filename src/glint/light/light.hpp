// Lights (paper §VI–VII).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/color.hpp"
#include "glint/geometry/hit.hpp"

namespace glint {

class Params;
struct BuildContext;

// Light arriving at a surface point from one sampled point of a light.
struct LightSample {
    Vec3 wi;                // unit direction from the surface towards the light
    Rgb radiance;           // arriving radiance (for a delta light, the irradiance-per-cosine I/r²)
    Vec3 position;          // the point on the light, for the shadow ray
    double pdf = 1;         // solid-angle density of wi; 1 for delta lights
    bool delta = true;      // a point or directional light: no other way to hit it
    bool infinite = false;  // at infinity: the shadow ray has no end point
};

class Light {
  public:
    virtual ~Light() = default;

    // Samples light arriving at `at`; nullopt when this light sends none there (or is only ambient).
    virtual std::optional<LightSample> sample(const Hit& at, Point2 u) const = 0;

    // Radiance of a uniform, unoccluded ambient term, added as material.ambient_reflectance · this.
    virtual Rgb ambient() const { return {}; }
};

using LightFactory = std::function<std::unique_ptr<Light>(Params&, const BuildContext&)>;
struct LightEntry {
    std::string name;
    LightFactory create;
};
// The name → constructor table of lights ("ambient", "point", …).
const std::vector<LightEntry>& light_table();

}  // namespace glint
