// Matte {type: matte, albedo}: albedo a colour or texture in [0, 1] per channel (above 1 would create
// energy), default 0.8.
#include "glint/material/matte.hpp"

#include "glint/params/params.hpp"

namespace glint {

Matte::Matte(std::shared_ptr<const Texture> albedo) : albedo_(std::move(albedo)) {
    if (const auto* constant = dynamic_cast<const ConstantTexture*>(albedo_.get())) {
        set_constant_lambert(constant->evaluate(Hit{}));
    }
}

Rgb Matte::evaluate(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const {
    return lambert_evaluate(point.diffuse, wo, wi);
}

std::optional<BsdfSample> Matte::sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const {
    return lambert_sample(point.diffuse, wo, u);
}

double Matte::pdf(const MaterialPoint&, const Vec3& wo, const Vec3& wi) const {
    return lambert_pdf(wo, wi);
}

std::unique_ptr<Material> Matte::create(Params& params, const BuildContext& context) {
    return std::make_unique<Matte>(read_reflectance(params, "albedo", Rgb(0.8), context));
}

}  // namespace glint
