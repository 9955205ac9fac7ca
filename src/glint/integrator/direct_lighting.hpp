#pragma once

#include "glint/core/color.hpp"
#include "glint/geometry/hit.hpp"
#include "glint/integrator/integrator.hpp"

namespace glint {

class Material;

// Light reflected towards wo at `hit` straight from the scene's lights: the ambient term plus, for
// each light, one sample of f · L · cos θ / pdf, with a shadow ray (paper §VI–VII). Shared by the
// integrators that shade with direct light.
Rgb direct_lighting(const Scene& scene, const Hit& hit, const Material& material, const Vec3& wo,
                    SampleStream& samples, RayCounters& rays);

}  // namespace glint
