// Phong {type: phong, diffuse, specular, exponent}:
//   diffuse   kd, colour or texture, default 0.5;
//   specular  ks, colour or texture, default 0.2; kd + ks must not exceed 1 (checked on the maxima);
//   exponent  n > 0, default 32: larger is shinier.
#include "glint/material/phong.hpp"

#include <cmath>

#include "glint/core/frame.hpp"
#include "glint/material/mirror.hpp"
#include "glint/params/params.hpp"

namespace glint {

double Phong::specular_probability(const Hit& hit) const {
    const double d = diffuse_->evaluate(hit).luminance();
    const double s = specular_->evaluate(hit).luminance();
    return d + s > 0 ? s / (d + s) : 0;
}

Rgb Phong::evaluate(const Hit& hit, const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(hit, wo, wi)) {
        return {};
    }
    const double cos_alpha = std::max(0.0, dot(mirror_direction(hit, wo), wi));
    const double lobe = (exponent_ + 2) * (0.5 * kInvPi) * std::pow(cos_alpha, exponent_);
    return diffuse_->evaluate(hit) * kInvPi + specular_->evaluate(hit) * lobe;
}

double Phong::pdf(const Hit& hit, const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(hit, wo, wi)) {
        return 0;
    }
    const double p = specular_probability(hit);
    const double cos_alpha = std::max(0.0, dot(mirror_direction(hit, wo), wi));
    const double lobe_pdf = (exponent_ + 1) * (0.5 * kInvPi) * std::pow(cos_alpha, exponent_);
    return (1 - p) * std::abs(dot(hit.shading_normal, wi)) * kInvPi + p * lobe_pdf;
}

std::optional<BsdfSample> Phong::sample(const Hit& hit, const Vec3& wo, Point2 u) const {
    const double p = specular_probability(hit);
    if (diffuse_->evaluate(hit).is_black() && p == 0) {
        return std::nullopt;
    }
    Vec3 wi;
    if (u.x < p) {
        // cos α = ξ^{1/(n+1)} has density (n + 1)/(2π) cosⁿα about the mirror direction.
        const double cos_alpha = std::pow(u.x / p, 1 / (exponent_ + 1));
        const double sin_alpha = safe_sqrt(1 - cos_alpha * cos_alpha);
        const double phi = 2 * kPi * u.y;
        wi = Frame::from_normal(mirror_direction(hit, wo))
                 .to_world({sin_alpha * std::cos(phi), sin_alpha * std::sin(phi), cos_alpha});
    } else {
        const Point2 v{(u.x - p) / (1 - p), u.y};
        wi = Frame::from_normal(face_forward(hit.shading_normal, wo)).to_world(sample_cosine_hemisphere(v));
    }
    const double density = pdf(hit, wo, wi);
    if (!(density > 0)) {
        return std::nullopt;  // a lobe direction below the surface
    }
    return BsdfSample{wi, evaluate(hit, wo, wi), density, false};
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
