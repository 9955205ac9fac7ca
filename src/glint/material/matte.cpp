// Matte {type: matte, albedo}: albedo a colour or texture in [0, 1] per channel (above 1 would create
// energy), default 0.8.
#include "glint/material/matte.hpp"

#include "glint/params/params.hpp"

namespace glint {

Rgb Matte::evaluate(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const {
    return same_hemisphere(wo, wi) ? point.diffuse * kInvPi : Rgb{};
}

std::optional<BsdfSample> Matte::sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const {
    // Cosine-weighted about the normal on wo's side.
    const Vec3 wi = sample_cosine_hemisphere(u);
    const double pdf = wi.z * kInvPi;
    if (pdf <= 0) {
        return std::nullopt;
    }
    // f · cos θ / pdf = (ρ/π) · cos θ / (cos θ/π) = ρ.
    return BsdfSample{flip_if_below(wi, wo.z), point.diffuse * kInvPi, pdf, false, point.diffuse};
}

double Matte::pdf(const MaterialPoint&, const Vec3& wo, const Vec3& wi) const {
    return same_hemisphere(wo, wi) ? std::abs(wi.z) * kInvPi : 0;
}

std::unique_ptr<Material> Matte::create(Params& params, const BuildContext& context) {
    return std::make_unique<Matte>(read_reflectance(params, "albedo", Rgb(0.8), context));
}

}  // namespace glint
