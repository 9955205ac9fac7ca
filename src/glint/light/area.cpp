#include "glint/light/area.hpp"

#include "glint/geometry/rectangle.hpp"
#include "glint/params/build_context.hpp"
#include "glint/params/params.hpp"

namespace glint {

namespace {
// The hit record of a point sampled on the light, for material.emitted().
Hit light_hit(const Vec3& point, const Vec3& normal) {
    Hit h;
    h.point = point;
    h.normal = normal;
    h.shading_normal = normal;
    h.t = 0;
    return h;
}
}  // namespace

bool emits_light(const Material& material) {
    const Vec3 n{0, 0, 1};
    return !material.emitted(light_hit({0, 0, 0}, n), n).is_black();
}

AreaLight::AreaLight(const Shape& shape, const Material& material, int samples)
    : shape_(&shape),
      material_(&material),
      samples_(samples),
      rectangle_(dynamic_cast<const Rectangle*>(&shape)),
      emitter_(dynamic_cast<const AreaEmitter*>(&material)) {}

namespace {
// The light sample of `seen`, whose emitted radiance towards the reference point is `radiance`.
std::optional<LightSample> light_sample(const SeenSample& seen, const Rgb& radiance) {
    if (radiance.is_black() || !std::isfinite(seen.pdf_solid_angle)) {
        return std::nullopt;
    }
    LightSample s;
    s.delta = false;
    s.wi = seen.wi;
    s.position = seen.point;
    s.pdf = seen.pdf_solid_angle;
    s.radiance = radiance;
    return s;
}
}  // namespace

std::optional<LightSample> AreaLight::sample(const Hit& at, Point2 u) const {
    if (rectangle_ && emitter_) {
        // What the general path below computes (a rectangle samples by area, as the default
        // Shape::sample_seen_from does), inline.
        const std::optional<SeenSample> seen = seen_from(at.point, rectangle_->point_at(u));
        return seen ? light_sample(*seen, emitter_->emitted_from(seen->normal, -seen->wi)) : std::nullopt;
    }
    const std::optional<SeenSample> seen = shape_->sample_seen_from(at.point, u);
    return seen ? sample_of(*seen) : std::nullopt;
}

std::optional<LightSample> AreaLight::sample_of(const SeenSample& seen) const {
    // An AreaEmitter reads only the normal: no Hit record to build for it (every light sample of
    // smallpt's sphere comes here).
    const Rgb radiance = emitter_ ? emitter_->emitted_from(seen.normal, -seen.wi)
                                  : material_->emitted(light_hit(seen.point, seen.normal), -seen.wi);
    return light_sample(seen, radiance);
}

double AreaLight::pdf(const Hit& at, const Vec3& wi, const Hit* on_light) const {
    return on_light ? shape_->pdf_seen_from(at.point, wi, *on_light) : 0;
}

std::unique_ptr<Light> AreaLight::create(Params& params, const BuildContext& context) {
    const Rgb radiance = params.non_negative_color("radiance", Rgb(1.0)) * params.non_negative("scale", 1.0);
    const bool two_sided = params.boolean("two_sided", false);
    const std::int64_t samples = params.positive_integer("samples", 1);
    if (samples > 4096) {
        params.fail("samples", "an area light takes at most 4096 shadow rays per shading point");
    }
    if (!context.add_object) {
        params.fail("an area light can only be built inside a scene");
    }
    Params shape_params = params.child("shape");
    const auto [shape, material] =
        context.add_object(shape_params, std::make_unique<AreaEmitter>(radiance, two_sided));
    if (!(shape->area() > 0)) {
        params.fail("shape", "an area light needs a shape with finite, non-zero area (not " +
                                 shape_params.what() + ")");
    }
    return std::make_unique<AreaLight>(*shape, *material, static_cast<int>(samples));
}

}  // namespace glint
