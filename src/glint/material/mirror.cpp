// Mirror {type: mirror, reflectance}: reflectance kr, colour or texture in [0, 1], default 1.
#include "glint/material/mirror.hpp"

#include "glint/params/params.hpp"

namespace glint {

std::optional<BsdfSample> Mirror::sample(const MaterialPoint& point, const Vec3& wo, Point2) const {
    const double cos_theta = std::abs(wo.z);
    if (cos_theta <= 0) {
        return std::nullopt;
    }
    return BsdfSample{mirror_local(wo), point.specular / cos_theta, 1.0, true, point.specular};
}

std::unique_ptr<Material> Mirror::create(Params& params, const BuildContext& context) {
    return std::make_unique<Mirror>(read_reflectance(params, "reflectance", Rgb(1.0), context));
}

}  // namespace glint
