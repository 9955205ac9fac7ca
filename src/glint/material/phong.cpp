// Phong {type: phong, diffuse, specular, exponent}:
//   diffuse   kd, colour or texture, default 0.5;
//   specular  ks, colour or texture, default 0.2; kd + ks must not exceed 1 (checked on the maxima);
//   exponent  n > 0, default 32: larger is shinier.
#include "glint/material/phong.hpp"

#include <cmath>

#include "glint/core/frame.hpp"
#include "glint/params/params.hpp"

namespace glint {

namespace {

// The probability of sampling the glossy lobe rather than the diffuse one: its share of the luminance.
double specular_probability(const MaterialPoint& point) {
    const double d = point.diffuse.luminance();
    const double s = point.specular.luminance();
    return d + s > 0 ? s / (d + s) : 0;
}

}  // namespace

Rgb Phong::evaluate(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(wo, wi)) {
        return {};
    }
    const double cos_alpha = std::max(0.0, dot(mirror_local(wo), wi));
    const double lobe = (exponent_ + 2) * (0.5 * kInvPi) * std::pow(cos_alpha, exponent_);
    return point.diffuse * kInvPi + point.specular * lobe;
}

double Phong::pdf(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(wo, wi)) {
        return 0;
    }
    const double p = specular_probability(point);
    const double cos_alpha = std::max(0.0, dot(mirror_local(wo), wi));
    const double lobe_pdf = (exponent_ + 1) * (0.5 * kInvPi) * std::pow(cos_alpha, exponent_);
    return (1 - p) * std::abs(wi.z) * kInvPi + p * lobe_pdf;
}

std::optional<BsdfSample> Phong::sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const {
    const double p = specular_probability(point);
    if (point.diffuse.is_black() && p == 0) {
        return std::nullopt;
    }
    Vec3 wi;
    if (u.x < p) {
        // cos α = ξ^{1/(n+1)} has density (n + 1)/(2π) cosⁿα about the mirror direction.
        const double cos_alpha = std::pow(u.x / p, 1 / (exponent_ + 1));
        const double sin_alpha = safe_sqrt(1 - cos_alpha * cos_alpha);
        const SinCos phi = sincos_turns(u.y);
        wi = Frame::from_normal(mirror_local(wo))
                 .to_world({sin_alpha * phi.cos, sin_alpha * phi.sin, cos_alpha});
    } else {
        const Point2 v{(u.x - p) / (1 - p), u.y};
        wi = flip_if_below(sample_cosine_hemisphere(v), wo.z);
    }
    const double density = pdf(point, wo, wi);
    if (!(density > 0)) {
        return std::nullopt;  // a lobe direction below the surface
    }
    return BsdfSample{wi, evaluate(point, wo, wi), density, false};
}

std::unique_ptr<Material> Phong::create(Params& params, const BuildContext& context) {
    auto diffuse = read_reflectance(params, "diffuse", Rgb(0.5), context);
    auto specular = read_reflectance(params, "specular", Rgb(0.2), context);
    if (diffuse->max_value() + specular->max_value() > 1) {
        params.fail("specular",
                    "phong diffuse + specular must not exceed 1 (energy conservation); their maxima are " +
                        std::to_string(diffuse->max_value()) + " and " +
                        std::to_string(specular->max_value()));
    }
    const double exponent = params.positive("exponent", 32);
    if (exponent > 1e6) {
        params.fail("exponent", "phong exponent must be at most 1e6 (use a mirror for a perfect reflection)");
    }
    return std::make_unique<Phong>(std::move(diffuse), std::move(specular), exponent);
}

}  // namespace glint
