#pragma once

#include "glint/integrator/integrator.hpp"

namespace glint {

// Ray casting: the first surface a camera ray meets, lit directly by every light, with hard shadows
// from shadow rays; no reflected or refracted rays. Rays that miss see the background.
class RaycastIntegrator final : public Integrator {
  public:
    Rgb radiance(const World& world, const Ray& ray, SampleStream& samples, RayCounters& rays) const override;
};

}  // namespace glint
