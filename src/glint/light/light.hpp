// Lights (paper §VI–VII).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/color.hpp"
#include "glint/geometry/hit.hpp"
#include "glint/params/name_table.hpp"

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
    // An ambient-occlusion probe: when the shadow ray is unblocked the surface gains
    // ambient_reflectance · radiance / (number of probes), not f · L cos θ / pdf.
    bool ambient = false;
};

class Light {
  public:
    virtual ~Light() = default;

    // Samples light arriving at `at`; nullopt when this light sends none there (or is only ambient).
    // at.shading_normal faces the side the surface is seen from (the integrators flip it so).
    virtual std::optional<LightSample> sample(const Hit& at, Point2 u) const = 0;

    // The solid-angle density with which sample() at `at` returns the direction wi, which meets this
    // light at `on_light` (a hit on the light's shape; nullptr for lights at infinity). 0 for delta
    // lights, which no ray can hit. Multiple importance sampling weighs BSDF-sampled rays with it.
    virtual double pdf(const Hit& /*at*/, const Vec3& /*wi*/, const Hit* /*on_light*/) const { return 0; }

    // Whether the path tracer should sample this light for next-event estimation. False for a light
    // whose radiance varies so little over the directions it covers that sampling the BSDF finds it
    // as well as sampling the light would: a shadow ray towards it would buy almost no variance, so
    // the path tracer leaves it to BSDF sampling, which then counts in full (pbrt-v4 does the same
    // for its uniform infinite light: `allowIncompletePDF`). Direct-lighting integrators, which have
    // no BSDF-sampled paths, sample every light whatever this says.
    virtual bool worth_sampling_in_paths() const { return true; }

    // Radiance arriving along a ray that leaves the scene in direction `dir` (unit): an environment's.
    virtual Rgb escaped(const Vec3& /*dir*/) const { return {}; }
    // Whether escaped() is this light's radiance: the scene keeps at most one such light, and it
    // replaces `background` (see docs/scene-format.md, "background").
    virtual bool is_environment() const { return false; }

    // Radiance of a uniform, unoccluded ambient term, added as material.ambient_reflectance · this.
    virtual Rgb ambient() const { return {}; }

    // Shadow rays per shading point for the direct-lighting integrators (raycast, whitted): lights with
    // area (soft shadows) and ambient occlusion average this many samples.
    virtual int samples() const { return 1; }

    // False for the non-physical ambient terms (ambient, ambient-occlusion), which the path tracer
    // leaves out: it finds indirect light by itself.
    virtual bool physical() const { return true; }
};

using LightFactory = std::function<std::unique_ptr<Light>(Params&, const BuildContext&)>;
struct LightEntry {
    std::string name;
    LightFactory create;
};
// The name → constructor table of lights ("ambient", "point", …).
const NameTable<LightEntry>& light_table();

}  // namespace glint
