// Plastic {type: plastic, diffuse, ior}:
//   diffuse  ρ of the base, colour or texture in [0, 1], default 0.5;
//   ior      refractive index of the coat, > 1, default 1.5.
#include "glint/material/plastic.hpp"

#include "glint/material/fresnel.hpp"
#include "glint/params/params.hpp"

namespace glint {

double Plastic::coat_reflectance(const Vec3& w) const {
    return fresnel_dielectric(std::abs(w.z), 1.0, ior_);
}

double Plastic::coat_probability(const MaterialPoint& point, const Vec3& wo) const {
    const double f = coat_reflectance(wo);
    const Rgb& rho = point.diffuse;
    const double base = (1 - f) * (rho.r + rho.g + rho.b) / 3;
    return f + base > 0 ? f / (f + base) : 1;
}

Rgb Plastic::evaluate(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(wo, wi)) {
        return {};
    }
    return point.diffuse * (kInvPi * (1 - coat_reflectance(wi)) * (1 - coat_reflectance(wo)));
}

double Plastic::pdf(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(wo, wi)) {
        return 0;
    }
    return (1 - coat_probability(point, wo)) * std::abs(wi.z) * kInvPi;
}

std::optional<BsdfSample> Plastic::sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const {
    const double cos_o = std::abs(wo.z);
    if (cos_o <= 0) {
        return std::nullopt;
    }
    const double p = coat_probability(point, wo);
    if (u.x < p) {
        const double reflectance = coat_reflectance(wo);
        return BsdfSample{mirror_local(wo), Rgb(reflectance / cos_o), p, true, Rgb(reflectance / p)};
    }
    const Point2 v{(u.x - p) / (1 - p), u.y};
    const Vec3 local = sample_cosine_hemisphere(v);
    if (local.z <= 0) {
        return std::nullopt;
    }
    const Vec3 wi = flip_if_below(local, wo.z);
    return BsdfSample{wi, evaluate(point, wo, wi), (1 - p) * local.z * kInvPi, false};
}

Rgb Plastic::ambient_reflectance(const MaterialPoint& point) const {
    const double r0 = fresnel_r0(1.0, ior_);
    return Rgb(r0) + sqr(1 - r0) * point.diffuse;
}

std::unique_ptr<Material> Plastic::create(Params& params, const BuildContext& context) {
    auto diffuse = read_reflectance(params, "diffuse", Rgb(0.5), context);
    const double ior = params.number("ior", 1.5);
    if (!(ior > 1) || ior > 10) {
        params.fail("ior", "plastic ior must lie in (1, 10]; about 1.5 for plastics");
    }
    return std::make_unique<Plastic>(std::move(diffuse), ior);
}

}  // namespace glint
