// Principled {type: principled, base_color, metallic, roughness, ior, specular}:
//   base_color  colour or texture in [0, 1], default 0.8: the base's albedo, and the metal's F₀;
//   metallic    number or texture in [0, 1], default 0 (a texture's value is the mean of its channels,
//               so an image texture with `channel: b` reads glTF's metallic-roughness map);
//   roughness   number or texture in [0, 1], default 0.5; α = roughness², as glTF (its map: `channel: g`);
//   ior         refractive index of the dielectric layer, [1, 10], default 1.5 (glTF's);
//   specular    scale of the dielectric's specular reflection, [0, 1], default 1 (KHR_materials_specular).
#include "glint/material/principled.hpp"

#include <algorithm>

#include "glint/material/fresnel.hpp"
#include "glint/material/microfacet.hpp"
#include "glint/params/params.hpp"

namespace glint {

namespace {

// A number read from a texture: the mean of its channels (the value itself for a grey texture).
double scalar_value(const Texture& texture, const Hit& hit) {
    const Rgb value = texture.evaluate(hit);
    return (value.r + value.g + value.b) / 3;
}

// A parameter in [0, 1] given as a number or a texture; values outside are an error at the key.
std::shared_ptr<const Texture> read_unit_texture(Params& params, const std::string& key, double fallback,
                                                 const BuildContext& context) {
    auto texture = read_texture(params, key, Rgb(fallback), context);  // rejects negative values
    if (texture->max_value() > 1) {
        params.fail(key, params.what() + "." + key + " must lie in [0, 1]");
    }
    return texture;
}

}  // namespace

Principled::Principled(std::shared_ptr<const Texture> base_color, std::shared_ptr<const Texture> metallic,
                       std::shared_ptr<const Texture> roughness, double ior, double specular)
    : base_color_(std::move(base_color)),
      metallic_(std::move(metallic)),
      roughness_(std::move(roughness)),
      ior_(ior),
      specular_(specular) {}

MaterialPoint Principled::look_up(const Hit& hit) const {
    const Rgb base = base_color_->evaluate(hit);
    const double metallic = scalar_value(*metallic_, hit);
    const double roughness = scalar_value(*roughness_, hit);
    return {(1 - metallic) * base, metallic * base, metallic,
            std::max(GgxDistribution::kMinAlpha, roughness * roughness)};
}

double Principled::dielectric_reflectance(double cos_theta) const {
    return specular_ * fresnel_dielectric(std::abs(cos_theta), 1.0, ior_);
}

// The specular lobe's share of the reflected light, estimated at θo: its Fresnel reflectance against
// what the base gets through the layer (the ratio plastic uses).
double Principled::specular_probability(const MaterialPoint& point, const Vec3& wo) const {
    const double layer = dielectric_reflectance(wo.z);
    const double cos_o = std::abs(wo.z);
    const double specular =
        schlick(cos_o, point.specular, point.metallic).luminance() + (1 - point.metallic) * layer;
    const double base = (1 - layer) * point.diffuse.luminance();
    return specular + base > 0 ? specular / (specular + base) : 1;
}

// Both directions on the same side, either side: the lobes take |z| as the cosines, and h = (wo + wi)/‖·‖
// lies on their side, so wo·h > 0.
Rgb Principled::evaluate(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(wo, wi)) {
        return {};
    }
    const Rgb base =
        point.diffuse * (kInvPi * (1 - dielectric_reflectance(wo.z)) * (1 - dielectric_reflectance(wi.z)));
    const Vec3 h = normalize(wo + wi);
    const double cos_oh = dot(wo, h);
    const Rgb fresnel = schlick(cos_oh, point.specular, point.metallic) +
                        Rgb((1 - point.metallic) * dielectric_reflectance(cos_oh));
    return base + fresnel * GgxDistribution(point.alpha).reflection(wo, wi, h);
}

double Principled::pdf(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const {
    if (!same_hemisphere(wo, wi)) {
        return 0;
    }
    const double p = specular_probability(point, wo);
    const double specular = GgxDistribution(point.alpha).reflection_pdf(wo, normalize(wo + wi));
    return p * specular + (1 - p) * std::abs(wi.z) * kInvPi;
}

std::optional<BsdfSample> Principled::sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const {
    if (wo.z == 0) {
        return std::nullopt;
    }
    const double p = specular_probability(point, wo);
    const Vec3 wi = u.x < p ? GgxDistribution(point.alpha).sample_reflection(wo, {u.x / p, u.y})
                            : flip_if_below(sample_cosine_hemisphere({(u.x - p) / (1 - p), u.y}), wo.z);
    // The density of wi under either lobe, so that MIS and sample() see one mixture density. A
    // direction in or below the surface (from a steep microfacet) has none and is rejected.
    const double density = pdf(point, wo, wi);
    if (!(density > 0) || !is_finite(wi)) {
        return std::nullopt;
    }
    return BsdfSample{wi, evaluate(point, wo, wi), density, false};
}

Rgb Principled::ambient_reflectance(const MaterialPoint& point) const {
    const double layer_r0 = specular_ * fresnel_r0(1.0, ior_);
    return point.specular + Rgb((1 - point.metallic) * layer_r0) + sqr(1 - layer_r0) * point.diffuse;
}

std::unique_ptr<Material> Principled::create(Params& params, const BuildContext& context) {
    auto base_color = read_reflectance(params, "base_color", Rgb(0.8), context);
    auto metallic = read_unit_texture(params, "metallic", 0.0, context);
    auto roughness = read_unit_texture(params, "roughness", 0.5, context);
    const double ior = params.number("ior", 1.5);
    if (!(ior >= 1 && ior <= 10)) {
        params.fail("ior", "principled ior must lie in [1, 10]; 1.5 for most dielectrics (glTF's default)");
    }
    const double specular = params.number("specular", 1.0);
    if (!(specular >= 0 && specular <= 1)) {
        params.fail("specular", "principled specular must lie in [0, 1]");
    }
    return std::make_unique<Principled>(std::move(base_color), std::move(metallic), std::move(roughness), ior,
                                        specular);
}

}  // namespace glint
