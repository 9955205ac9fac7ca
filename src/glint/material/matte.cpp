// Matte {type: matte, albedo}: albedo a colour or texture in [0, 1] per channel (above 1 would create
// energy), default 0.8.
#include "glint/material/matte.hpp"

#include "glint/core/frame.hpp"
#include "glint/params/params.hpp"

namespace glint {

Rgb Matte::evaluate(const Hit& hit, const Vec3& wo, const Vec3& wi) const {
    return same_hemisphere(hit, wo, wi) ? albedo_->evaluate(hit) * kInvPi : Rgb{};
}

std::optional<BsdfSample> Matte::sample(const Hit& hit, const Vec3& wo, Point2 u) const {
    // Cosine-weighted hemisphere around the normal on wo's side.
    const Vec3 local = sample_cosine_hemisphere(u);
    const Vec3 wi = Frame::from_normal(face_forward(hit.shading_normal, wo)).to_world(local);
    const double pdf = local.z * kInvPi;
    if (pdf <= 0) {
        return std::nullopt;
    }
    return BsdfSample{wi, albedo_->evaluate(hit) * kInvPi, pdf, false};
}

double Matte::pdf(const Hit& hit, const Vec3& wo, const Vec3& wi) const {
    return same_hemisphere(hit, wo, wi) ? std::abs(dot(hit.shading_normal, wi)) * kInvPi : 0;
}

std::unique_ptr<Material> Matte::create(Params& params, const BuildContext& context) {
    return std::make_unique<Matte>(read_reflectance(params, "albedo", Rgb(0.8), context));
}

}  // namespace glint
