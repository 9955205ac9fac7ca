// Metal {type: metal | glossy, reflectance, roughness}:
//   reflectance  (or `albedo`) F₀, colour or texture in [0, 1], default 0.9;
//   roughness    in [0, 1], default 0.3; α = roughness². `fuzz` (Ray Tracing in One Weekend's name) is
//                accepted instead and read as roughness: both blur the mirror image from sharp (0) to
//                very rough (1), though RTIOW's fuzz is a random offset and not a microfacet model.
#include "glint/material/metal.hpp"

#include "glint/material/fresnel.hpp"
#include "glint/params/params.hpp"

namespace glint {

// Both lobe directions on the same side, either side (GgxDistribution takes |z| as the cosines).
Rgb Metal::evaluate(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const {
    if (is_mirror() || !same_hemisphere(wo, wi)) {
        return {};
    }
    const Vec3 h = normalize(wo + wi);
    return schlick(dot(wo, h), point.specular) * ggx_.reflection(wo, wi, h);
}

double Metal::pdf(const MaterialPoint&, const Vec3& wo, const Vec3& wi) const {
    if (is_mirror() || !same_hemisphere(wo, wi)) {
        return 0;
    }
    return ggx_.reflection_pdf(wo, normalize(wo + wi));
}

std::optional<BsdfSample> Metal::sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const {
    const double cos_o = std::abs(wo.z);
    if (cos_o <= 0) {
        return std::nullopt;
    }
    if (is_mirror()) {
        const Rgb reflectance = schlick(cos_o, point.specular);
        return BsdfSample{mirror_local(wo), reflectance / cos_o, 1.0, true, reflectance};
    }
    const Vec3 wi = ggx_.sample_reflection(wo, u);
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
