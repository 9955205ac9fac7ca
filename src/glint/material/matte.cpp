// Matte {type: matte, albedo: [r, g, b]}: albedo in [0, 1] per channel (above 1 would create energy).
#include "glint/material/matte.hpp"

#include "glint/core/frame.hpp"
#include "glint/scene/params.hpp"

namespace glint {

namespace {
// wo and wi on the same side of the surface: Lambertian surfaces reflect, never transmit.
bool same_hemisphere(const Hit& hit, const Vec3& wo, const Vec3& wi) {
    return dot(hit.shading_normal, wo) * dot(hit.shading_normal, wi) > 0;
}
}  // namespace

Rgb Matte::evaluate(const Hit& hit, const Vec3& wo, const Vec3& wi) const {
    return same_hemisphere(hit, wo, wi) ? albedo_ * kInvPi : Rgb{};
}

std::optional<BsdfSample> Matte::sample(const Hit& hit, const Vec3& wo, Point2 u) const {
    // Cosine-weighted hemisphere around the normal on wo's side (Malley's method).
    const Vec3 n = face_forward(hit.shading_normal, wo);
    const double r = std::sqrt(u.x);
    const double phi = 2 * kPi * u.y;
    const Vec3 local{r * std::cos(phi), r * std::sin(phi), safe_sqrt(1 - u.x)};
    const Vec3 wi = Frame::from_normal(n).to_world(local);
    const double pdf = local.z * kInvPi;
    if (pdf <= 0) {
        return std::nullopt;
    }
    return BsdfSample{wi, albedo_ * kInvPi, pdf, false};
}

double Matte::pdf(const Hit& hit, const Vec3& wo, const Vec3& wi) const {
    return same_hemisphere(hit, wo, wi) ? std::abs(dot(hit.shading_normal, wi)) * kInvPi : 0;
}

std::unique_ptr<Material> Matte::create(Params& params, const BuildContext&) {
    const Rgb albedo = params.color("albedo", Rgb(0.8));
    if (albedo.r < 0 || albedo.g < 0 || albedo.b < 0 || albedo.max_component() > 1) {
        params.fail("albedo",
                    "matte albedo must lie in [0, 1] per channel (a surface cannot reflect more light than "
                    "it receives)");
    }
    return std::make_unique<Matte>(albedo);
}

}  // namespace glint
