#include "glint/light/point.hpp"

#include "glint/params/params.hpp"

namespace glint {

std::optional<LightSample> PointLight::sample(const Hit& at, Point2) const {
    const Vec3 to_light = position_ - at.point;
    const double distance_squared = length_squared(to_light);
    if (distance_squared == 0) {
        return std::nullopt;
    }
    LightSample s;
    s.wi = to_light / std::sqrt(distance_squared);
    s.radiance = intensity_ / distance_squared;  // inverse-square falloff
    s.position = position_;
    return s;
}

std::unique_ptr<Light> PointLight::create(Params& params, const BuildContext&) {
    const Vec3 position = params.vec3("position");
    const Rgb intensity =
        params.non_negative_color("intensity", Rgb(1.0)) * params.non_negative("scale", 1.0);
    return std::make_unique<PointLight>(position, intensity);
}

}  // namespace glint
