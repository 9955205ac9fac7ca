#include "glint/light/directional.hpp"

#include "glint/params/params.hpp"

namespace glint {

std::optional<LightSample> DirectionalLight::sample(const Hit& at, Point2) const {
    LightSample s;
    s.wi = to_light_;
    s.radiance = irradiance_;  // a delta in direction: the "radiance" is the irradiance per cosine
    s.position = at.point + to_light_;
    s.infinite = true;
    return s;
}

std::unique_ptr<Light> DirectionalLight::create(Params& params, const BuildContext&) {
    const Vec3 direction = params.direction("direction");
    const Rgb irradiance =
        params.non_negative_color("irradiance", Rgb(1.0)) * params.non_negative("scale", 1.0);
    return std::make_unique<DirectionalLight>(direction, irradiance);
}

}  // namespace glint
