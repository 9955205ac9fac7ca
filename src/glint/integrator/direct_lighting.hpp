#pragma once

#include "glint/core/color.hpp"
#include "glint/geometry/hit.hpp"
#include "glint/integrator/integrator.hpp"
#include "glint/light/light.hpp"

namespace glint {

class Bsdf;

// A shadow ray stops this short of the light's point, so the light's own surface (for lights with one)
// does not shadow itself; relative, so it holds at any scene scale.
inline constexpr double kShadowRayEnd = 1.0 - 1e-9;

// `hit` with its shading normal turned to the side `wo` sees: what Light::sample expects.
Hit facing(const Hit& hit, const Vec3& wo);

// Whether something blocks the shadow ray from `hit` to the light sample (counted in `rays`).
bool shadowed(const World& world, const Hit& hit, const LightSample& ls, RayCounters& rays);

// Light reflected towards wo at `hit`, of BSDF `bsdf`, straight from the scene's lights: the ambient term
// plus, for each light, the mean of light.samples() samples of f · L · cos θ / pdf, each with a shadow ray
// (paper §VI–VII); ambient-occlusion probes add the ambient term where unblocked. Shared by the
// integrators that shade with direct light.
Rgb direct_lighting(const World& world, const Hit& hit, const Bsdf& bsdf, const Vec3& wo,
                    SampleStream& samples, RayCounters& rays);

}  // namespace glint
