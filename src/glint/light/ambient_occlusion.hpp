#pragma once

#include "glint/light/light.hpp"

namespace glint {

// Ambient occlusion {type: ambient-occlusion, radiance: L, samples: n, distance: d}: the ambient light
// of Suffern ch. 17, shadowed. Each shading point casts n probe rays over the cosine-weighted
// hemisphere around its normal; each probe that meets nothing within `distance` (default: unlimited)
// adds ambient_reflectance · L / n. Open surfaces get the full ambient term, creases and contact
// points get less. A non-physical term: the path tracer leaves it out.
class AmbientOcclusionLight final : public Light {
  public:
    AmbientOcclusionLight(const Rgb& radiance, int samples, double distance)
        : radiance_(radiance), samples_(samples), distance_(distance) {}
    std::optional<LightSample> sample(const Hit& at, Point2 u) const override;
    int samples() const override { return samples_; }
    bool physical() const override { return false; }

    static std::unique_ptr<Light> create(Params& params, const BuildContext& context);

  private:
    Rgb radiance_;
    int samples_;
    double distance_;  // kInf: unlimited
};

}  // namespace glint
