// Metal {type: metal | glossy, reflectance, roughness}:
//   reflectance  (or `albedo`) F₀, colour or texture in [0, 1], default 0.9;
//   roughness    in [0, 1], default 0.3; α = roughness². `fuzz` (Ray Tracing in One Weekend's name) is
//                accepted instead and read as roughness: both blur the mirror image from sharp (0) to
//                very rough (1), though RTIOW's fuzz is a random offset and not a microfacet model.
#include "glint/material/metal.hpp"

#include "glint/material/fresnel.hpp"
#include "glint/params/params.hpp"

namespace glint {

double Metal::distribution(double cos_h) const {
    const double a2 = alpha_ * alpha_;
    const double d = cos_h * cos_h * (a2 - 1) + 1;
    return a2 / (kPi * d * d);
}

double Metal::lambda(double cos_theta) const {
    const double c2 = cos_theta * cos_theta;
    const double tan2 = std::max(0.0, 1 - c2) / c2;
    return 0.5 * (std::sqrt(1 + alpha_ * alpha_ * tan2) - 1);
}

// Both lobe directions on the same side, either side: the normal on wo's side is (0, 0, ±1), so the
// cosines are |z| and the half vector's cosine |h.z| (h lies on their side too).
Rgb Metal::evaluate(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const {
    if (is_mirror() || !same_hemisphere(wo, wi)) {
        return {};
    }
    const double cos_o = std::abs(wo.z), cos_i = std::abs(wi.z);
    const Vec3 h = normalize(wo + wi);
    const double g = 1 / (1 + lambda(cos_o) + lambda(cos_i));
    return schlick(dot(wo, h), point.specular) * (distribution(std::abs(h.z)) * g / (4 * cos_o * cos_i));
}

double Metal::pdf(const MaterialPoint&, const Vec3& wo, const Vec3& wi) const {
    if (is_mirror() || !same_hemisphere(wo, wi)) {
        return 0;
    }
    const double cos_o = std::abs(wo.z);
    const Vec3 h = normalize(wo + wi);
    return distribution(std::abs(h.z)) / ((1 + lambda(cos_o)) * 4 * cos_o);
}

std::optional<BsdfSample> Metal::sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const {
    const double cos_o = std::abs(wo.z);
    if (cos_o <= 0) {
        return std::nullopt;
    }
    if (is_mirror()) {
        return BsdfSample{mirror_local(wo), schlick(cos_o, point.specular) / cos_o, 1.0, true};
    }
    // Visible normals (Heitz 2018), with wo turned above the surface: stretch wo to the unit-roughness
    // configuration, sample the projected hemisphere seen from it, and unstretch the normal.
    const Vec3 o = flip_if_below(wo, wo.z);
    const Vec3 vh = normalize(Vec3{alpha_ * o.x, alpha_ * o.y, o.z});
    const double len2 = vh.x * vh.x + vh.y * vh.y;
    const Vec3 t1 = len2 > 0 ? Vec3{-vh.y, vh.x, 0} / std::sqrt(len2) : Vec3{1, 0, 0};
    const Vec3 t2 = cross(vh, t1);
    const double r = std::sqrt(u.x);
    const SinCos phi = sincos_turns(u.y);
    const double p1 = r * phi.cos;
    const double s = 0.5 * (1 + vh.z);
    const double p2 = (1 - s) * safe_sqrt(1 - p1 * p1) + s * r * phi.sin;
    const Vec3 nh = p1 * t1 + p2 * t2 + safe_sqrt(1 - p1 * p1 - p2 * p2) * vh;
    const Vec3 m = normalize(Vec3{alpha_ * nh.x, alpha_ * nh.y, std::max(1e-12, nh.z)});
    const Vec3 wi = flip_if_below(2 * dot(o, m) * m - o, wo.z);
    const double density = pdf(point, wo, wi);
    if (!(density > 0) || !is_finite(wi)) {
        return std::nullopt;  // reflected below the surface
    }
    return BsdfSample{wi, evaluate(point, wo, wi), density, false};
}

std::unique_ptr<Material> Metal::create(Params& params, const BuildContext& context) {
    if (params.has("reflectance") && params.has("albedo")) {
        params.fail("albedo", "give the metal's colour as `reflectance` or `albedo`, not both");
    }
    auto reflectance =
        read_reflectance(params, params.has("albedo") ? "albedo" : "reflectance", Rgb(0.9), context);
    if (params.has("roughness") && params.has("fuzz")) {
        params.fail("fuzz", "give `roughness` or `fuzz` (its alias), not both");
    }
    const std::string key = params.has("fuzz") ? "fuzz" : "roughness";
    const double roughness = params.number(key, 0.3);
    if (!(roughness >= 0 && roughness <= 1)) {
        params.fail(key, "metal " + key + " must lie in [0, 1]");
    }
    return std::make_unique<Metal>(std::move(reflectance), roughness);
}

}  // namespace glint
