#include "glint/light/ambient_occlusion.hpp"

#include "glint/core/frame.hpp"
#include "glint/material/material.hpp"
#include "glint/params/params.hpp"

namespace glint {

std::optional<LightSample> AmbientOcclusionLight::sample(const Hit& at, Point2 u) const {
    // Cosine-weighted directions: probes fall where an ambient term weighs most.
    const Vec3 local = sample_cosine_hemisphere(u);
    LightSample s;
    s.wi = Frame::from_normal(at.shading_normal).to_world(local);
    s.radiance = radiance_;
    s.pdf = local.z * kInvPi;
    s.ambient = true;
    s.delta = false;
    if (distance_ == kInf) {
        s.infinite = true;
        s.position = at.point + s.wi;
    } else {
        s.position = at.point + s.wi * distance_;
    }
    return s;
}

std::unique_ptr<Light> AmbientOcclusionLight::create(Params& params, const BuildContext&) {
    const Rgb radiance = params.non_negative_color("radiance", Rgb(0.1)) * params.non_negative("scale", 1.0);
    const std::int64_t samples = params.positive_integer("samples", 16);
    if (samples > 4096) {
        params.fail("samples", "ambient-occlusion samples must be at most 4096 per shading point");
    }
    const double distance = params.has("distance") ? params.positive("distance") : kInf;
    return std::make_unique<AmbientOcclusionLight>(radiance, static_cast<int>(samples), distance);
}

}  // namespace glint
