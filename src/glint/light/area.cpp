#include "glint/light/area.hpp"

#include "glint/core/frame.hpp"
#include "glint/geometry/sphere.hpp"
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
    : shape_(&shape), material_(&material), sphere_(dynamic_cast<const Sphere*>(&shape)), samples_(samples) {}

bool AreaLight::sees_sphere_from_outside(const Vec3& p) const {
    // A margin of relative 1e-9 keeps points on the surface (rounding either way) on area sampling.
    return sphere_ && length_squared(p - sphere_->center()) > sqr(sphere_->radius()) * (1 + 1e-9);
}

namespace {
// 1 − cos θ_max of the cone a sphere subtends, from sin² θ_max = R²/d², without cancellation:
// 1 − cos = sin² / (1 + cos).
double one_minus_cos_max(double sin2_max) {
    return sin2_max / (1 + safe_sqrt(1 - sin2_max));
}
}  // namespace

std::optional<LightSample> AreaLight::sample(const Hit& at, Point2 u) const {
    LightSample s;
    s.delta = false;
    Vec3 normal;
    if (sees_sphere_from_outside(at.point)) {
        // Uniform direction in the cone towards the sphere, then the point of the sphere it meets
        // (pbrt-v4 §6.2.4, with the angle α at the centre computed directly).
        const Vec3 to_center = sphere_->center() - at.point;
        const double d2 = length_squared(to_center);
        const double sin2_max = sqr(sphere_->radius()) / d2;
        const double sin_max = std::sqrt(sin2_max);
        const double omc_max = one_minus_cos_max(sin2_max);
        const double omc = u.x * omc_max;  // 1 − cos θ, uniform in [0, 1 − cos θ_max]
        const double cos_theta = 1 - omc;
        const double sin2_theta = omc * (2 - omc);
        const double cos_alpha = sin2_theta / sin_max + cos_theta * safe_sqrt(1 - sin2_theta / sin2_max);
        const double sin_alpha = safe_sqrt(1 - cos_alpha * cos_alpha);
        const double phi = 2 * kPi * u.y;
        const Frame frame = Frame::from_normal(to_center / std::sqrt(d2));
        normal = frame.to_world({-sin_alpha * std::cos(phi), -sin_alpha * std::sin(phi), -cos_alpha});
        s.position = sphere_->center() + sphere_->radius() * normal;
        s.pdf = 1 / (2 * kPi * omc_max);
        const Vec3 to_light = s.position - at.point;
        const double distance = length(to_light);
        if (!(distance > 0)) {
            return std::nullopt;
        }
        s.wi = to_light / distance;
    } else {
        const std::optional<ShapeSample> ss = shape_->sample_area(u);
        if (!ss) {
            return std::nullopt;
        }
        const Vec3 to_light = ss->point - at.point;
        const double d2 = length_squared(to_light);
        if (!(d2 > 0)) {
            return std::nullopt;
        }
        s.wi = to_light / std::sqrt(d2);
        const double cos_light = std::abs(dot(ss->normal, s.wi));
        if (cos_light == 0) {
            return std::nullopt;
        }
        s.position = ss->point;
        s.pdf = ss->pdf_area * d2 / cos_light;  // area density → solid-angle density
        normal = ss->normal;
    }
    s.radiance = material_->emitted(light_hit(s.position, normal), -s.wi);
    if (s.radiance.is_black() || !std::isfinite(s.pdf)) {
        return std::nullopt;
    }
    return s;
}

double AreaLight::pdf(const Hit& at, const Vec3& wi, const Hit* on_light) const {
    if (sees_sphere_from_outside(at.point)) {
        return 1 / (2 * kPi *
                    one_minus_cos_max(sqr(sphere_->radius()) / length_squared(sphere_->center() - at.point)));
    }
    if (!on_light) {
        return 0;
    }
    const double cos_light = std::abs(dot(on_light->normal, wi));
    if (cos_light == 0) {
        return 0;
    }
    return length_squared(on_light->point - at.point) / (cos_light * shape_->area());
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
