#include "glint/light/spot.hpp"

#include "glint/params/params.hpp"

namespace glint {

double SpotLight::falloff(double cos_theta) const {
    if (cos_theta >= cos_inner_) {
        return 1;
    }
    if (cos_theta <= cos_outer_) {
        return 0;
    }
    const double t = (cos_theta - cos_outer_) / (cos_inner_ - cos_outer_);
    return t * t * (3 - 2 * t);  // smoothstep: no visible edge where the falloff starts or ends
}

std::optional<LightSample> SpotLight::sample(const Hit& at, Point2) const {
    const Vec3 to_light = position_ - at.point;
    const double distance_squared = length_squared(to_light);
    if (distance_squared == 0) {
        return std::nullopt;
    }
    LightSample s;
    s.wi = to_light / std::sqrt(distance_squared);
    const double f = falloff(dot(-s.wi, axis_));
    if (f == 0) {
        return std::nullopt;
    }
    s.radiance = intensity_ * (f / distance_squared);
    s.position = position_;
    return s;
}

std::unique_ptr<Light> SpotLight::create(Params& params, const BuildContext&) {
    const Vec3 position = params.vec3("position");
    Vec3 direction;
    if (params.has("look_at")) {
        if (params.has("direction")) {
            params.fail("direction", "give a spot light either `direction` or `look_at`, not both");
        }
        direction = params.vec3("look_at") - position;
        if (length_squared(direction) == 0) {
            params.fail("look_at", "the spot light's look_at must differ from its position");
        }
    } else {
        direction = params.direction("direction", {0, -1, 0});
    }
    const Rgb intensity =
        params.non_negative_color("intensity", Rgb(1.0)) * params.non_negative("scale", 1.0);
    const double angle = params.number("angle", 30.0);
    if (!(angle > 0 && angle <= 180)) {
        params.fail("angle", "the spot light's cone half-angle must lie in (0, 180] degrees");
    }
    const double falloff_angle = params.number("falloff_angle", angle * 0.8);
    if (!(falloff_angle >= 0 && falloff_angle <= angle)) {
        params.fail("falloff_angle", "falloff_angle (where the falloff starts) must lie in [0, angle]");
    }
    return std::make_unique<SpotLight>(position, direction, intensity, std::cos(radians(angle)),
                                       std::cos(radians(falloff_angle)));
}

}  // namespace glint
