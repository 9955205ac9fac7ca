// The principled (glTF metallic-roughness) material against values known without its code: Lambert at
// ior 1, the metal's F₀ at normal incidence, the glass Fresnel figures plastic's test uses, white
// furnaces, glint's metal at metallic 1 and the linear blend in `metallic`. The shared sampling/pdf/χ²
// checks run on it in bsdf_test.cpp (the Principled* cases), its keys in material_params_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "glint/material/metal.hpp"
#include "glint/material/principled.hpp"
#include "material/bsdf_checks.hpp"

namespace glint {
namespace {

using testing::direction_at;
using testing::estimate_albedo;
using testing::test_hit;
using testing::test_point;

std::shared_ptr<const Texture> constant(const Rgb& value) {
    return std::make_shared<ConstantTexture>(value);
}

Principled principled(const Rgb& base_color, double metallic, double roughness, double ior = 1.5) {
    return Principled(constant(base_color), constant(Rgb(metallic)), constant(Rgb(roughness)), ior, 1.0);
}

// The mean path weight f |cos θi| / pdf per channel, from the material's own samples: its albedo in
// each colour (estimate_albedo gives the luminance only).
Rgb albedo_per_channel(const Material& material, const Hit& hit, const Vec3& wo, int samples,
                       std::uint64_t seed) {
    const Bsdf bsdf = material.bsdf(hit);
    Rgb sum;
    for (int i = 0; i < samples; ++i) {
        const auto s = bsdf.sample(wo, test_point(seed, static_cast<std::uint32_t>(i)));
        if (s && s->pdf > 0) {
            sum = sum + s->f * (std::abs(dot(hit.shading_normal, s->wi)) / s->pdf);
        }
    }
    return sum / samples;
}

// `count` pairs (wo, wi) of directions on the same side of the hit's surface, alternately above and
// below, from grazing (cos θ = 0.02) to the normal.
std::vector<std::pair<Vec3, Vec3>> direction_pairs(const Hit& hit, std::uint64_t seed, std::uint32_t count) {
    std::vector<std::pair<Vec3, Vec3>> pairs;
    for (std::uint32_t i = 0; i < count; ++i) {
        const SampleKey key{seed, i, 0, 0};
        const double side = i % 2 == 0 ? 1 : -1;
        pairs.emplace_back(direction_at(hit, side * (0.02 + 0.98 * key.uniform(0)), 7 * key.uniform(1)),
                           direction_at(hit, side * (0.02 + 0.98 * key.uniform(2)), 7 * key.uniform(3)));
    }
    return pairs;
}

// a and b equal per channel within `tolerance` times the larger of 1 and b's channel.
void expect_near(const Rgb& a, const Rgb& b, double tolerance) {
    EXPECT_NEAR(a.r, b.r, tolerance * std::max(1.0, b.r));
    EXPECT_NEAR(a.g, b.g, tolerance * std::max(1.0, b.g));
    EXPECT_NEAR(a.b, b.b, tolerance * std::max(1.0, b.b));
}

// Viewing directions from near the normal to grazing, and one from the back side of the surface.
const double kViewCosines[] = {1.0, 0.7, 0.4, 0.15, 0.05, -0.6};

TEST(Principled, DielectricOfIorOneIsLambertian) {
    // ior 1: no interface, F = 0, so neither a specular lobe nor a loss through the layer.
    const Rgb base(0.7, 0.5, 0.2);
    const Principled material = principled(base, 0, 1.0, 1.0);
    const Hit hit = test_hit();
    const Bsdf bsdf = material.bsdf(hit);
    std::uint32_t i = 0;
    for (const auto& [wo, wi] : direction_pairs(hit, 4, 200)) {
        expect_near(bsdf.evaluate(wo, wi), base / kPi, 1e-12);
        EXPECT_TRUE(bsdf.evaluate(wo, -wi).is_black()) << "no transmission";
        // Sampled as Lambert, cosine-weighted: each path weight is the albedo itself.
        const auto s = bsdf.sample(wo, test_point(5, i++));
        ASSERT_TRUE(s);
        const double cos_i = std::abs(dot(hit.shading_normal, s->wi));
        EXPECT_NEAR(s->pdf, cos_i / kPi, 1e-12);
        expect_near(s->f * (cos_i / s->pdf), base, 1e-12);
    }
}

TEST(Principled, SmoothMetalReflectsItsBaseColourAtNormalIncidence) {
    // F₀ = base colour: at normal incidence a nearly smooth metal reflects it (Schlick is F₀ at cos 1,
    // and GGX at α = 0.0025 loses nothing measurable).
    const Rgb gold(1.0, 0.78, 0.34);
    const Hit hit = test_hit();
    const Principled metal = principled(gold, 1, 0.05);
    const Rgb albedo = albedo_per_channel(metal, hit, hit.shading_normal, 20000, 7);
    expect_near(albedo, gold, 5e-3);
    // Towards grazing angles Schlick's Fresnel rises to 1: the blue channel reflects more.
    const Rgb grazing = albedo_per_channel(metal, hit, direction_at(hit, 0.1, 0.4), 20000, 8);
    EXPECT_GT(grazing.b, gold.b + 0.1);
}

TEST(Principled, MetallicOneIsGlintsMetal) {
    // glTF's metal_brdf is the GGX lobe with Schlick's Fresnel of F₀ = base colour: glint's `metal`.
    const Rgb copper(0.95, 0.64, 0.54);
    const Principled principled_metal = principled(copper, 1, 0.45);
    const Metal metal(constant(copper), 0.45);
    const Hit hit = test_hit();
    for (const auto& [wo, wi] : direction_pairs(hit, 14, 200)) {
        expect_near(principled_metal.bsdf(hit).evaluate(wo, wi), metal.bsdf(hit).evaluate(wo, wi), 1e-12);
        const double pdf = metal.bsdf(hit).pdf(wo, wi);
        EXPECT_NEAR(principled_metal.bsdf(hit).pdf(wo, wi), pdf, 1e-12 * std::max(1.0, pdf));
    }
}

TEST(Principled, SmoothWhiteDielectricReflectsLikePlastic) {
    // At normal incidence the layer reflects F₀ = 0.04 (ior 1.5) and passes the rest to a white base,
    // which returns what the layer lets out: 1 − 0.0918, the cosine-weighted hemispherical Fresnel
    // reflectance of glass (the figure plastic's furnace test uses).
    const Principled material = principled(Rgb(1.0), 0, 0.0, 1.5);
    const Hit hit = test_hit();
    const auto e = estimate_albedo(material, hit, hit.shading_normal, 40000, 9);
    const double f0 = 0.04;
    EXPECT_NEAR(e.mean, f0 + (1 - f0) * (1 - 0.0918), 4 * e.standard_error + 2e-3);
}

TEST(Principled, WhiteMetalLosesOnlyTheSingleScatteringShareOfGgx) {
    // Schlick with F₀ = 1 is 1 at every angle, so the albedo is GGX's single-scattering albedo: at most
    // 1, near 1 for a smooth surface, and lower (light lost between microfacets) as it gets rougher.
    const Hit hit = test_hit();
    double previous = 1.0;
    for (const double roughness : {0.0, 0.1, 0.3, 0.6, 1.0}) {
        const Principled metal = principled(Rgb(1.0), 1, roughness);
        for (const double c : kViewCosines) {
            const auto e = estimate_albedo(metal, hit, direction_at(hit, c, 0.9), 40000, 10);
            EXPECT_LE(e.mean, 1 + 4 * e.standard_error) << "roughness " << roughness << ", cos θo " << c;
            if (roughness <= 0.1) {
                EXPECT_GE(e.mean, 0.95) << "roughness " << roughness << ", cos θo " << c;
            }
        }
        const auto normal = estimate_albedo(metal, hit, hit.shading_normal, 100000, 11);
        EXPECT_LE(normal.mean, previous + 4 * normal.standard_error) << "roughness " << roughness;
        previous = normal.mean;
        if (roughness == 1.0) {
            // At α = 1 the albedo at normal incidence has a closed form. D = 1/π, so the normals visible
            // from wo = n are cosine-distributed; wi, the reflection of n about h, lies at θi = 2θh (below
            // the surface for θh > 45°), and each sample weighs G/G₁(wo) = 1/(1 + Λ(wi)) with
            // Λ(θ) = (1/cos θ − 1)/2. With s = sin²θh (uniform in [0, 1]) the weight is (1 − 2s)/(1 − s)
            // for s < ½, and ∫₀^½ (1 − 2s)/(1 − s) ds = 1 − ln 2.
            EXPECT_NEAR(normal.mean, 1 - std::log(2.0), 4 * normal.standard_error);
        }
    }
}

TEST(Principled, WhiteDielectricConservesEnergyAtEveryAngleAndRoughness) {
    // The base gets only what the layer transmits, (1 − F(θo)) (1 − F(θi)): the specular and diffuse
    // parts together never reflect more than arrives, even at grazing angles where the layer is bright.
    const Hit hit = test_hit();
    for (const double roughness : {0.0, 0.1, 0.3, 0.6, 1.0}) {
        for (const double ior : {1.5, 3.0}) {
            const Principled material = principled(Rgb(1.0), 0, roughness, ior);
            for (const double c : kViewCosines) {
                const auto e = estimate_albedo(material, hit, direction_at(hit, c, 2.2), 20000, 12);
                EXPECT_LE(e.mean, 1 + 4 * e.standard_error)
                    << "roughness " << roughness << ", ior " << ior << ", cos θo " << c;
                EXPECT_GT(e.mean, 0.2) << "roughness " << roughness << ", ior " << ior << ", cos θo " << c;
            }
        }
    }
}

TEST(Principled, IsTheLinearBlendOfDielectricAndMetalInMetallic) {
    // glTF: f = mix(dielectric_brdf, metal_brdf, metallic), for any pair of directions.
    const Rgb base(0.9, 0.4, 0.1);
    const Principled dielectric = principled(base, 0, 0.4), metal = principled(base, 1, 0.4),
                     blend = principled(base, 0.3, 0.4);
    const Hit hit = test_hit();
    for (const auto& [wo, wi] : direction_pairs(hit, 13, 200)) {
        const Rgb expected =
            0.7 * dielectric.bsdf(hit).evaluate(wo, wi) + 0.3 * metal.bsdf(hit).evaluate(wo, wi);
        expect_near(blend.bsdf(hit).evaluate(wo, wi), expected, 1e-12);
    }
}

TEST(Principled, ATexturedParameterIsTheMeanOfItsChannels) {
    const Hit hit = test_hit();
    const Principled textured(constant(Rgb(0.8)), constant(Rgb(0.1, 0.4, 0.7)), constant(Rgb(0.2, 0.3, 0.7)),
                              1.5, 1.0);
    const Principled plain = principled(Rgb(0.8), 0.4, 0.4);
    const Vec3 wo = direction_at(hit, 0.6, 0.3), wi = direction_at(hit, 0.8, 2.5);
    expect_near(textured.bsdf(hit).evaluate(wo, wi), plain.bsdf(hit).evaluate(wo, wi), 1e-12);
    EXPECT_NEAR(textured.bsdf(hit).pdf(wo, wi), plain.bsdf(hit).pdf(wo, wi), 1e-12);
}

TEST(Principled, AmbientReflectanceIsTheNormalIncidenceReflectance) {
    const Hit hit = test_hit();
    const Rgb gold(1.0, 0.78, 0.34);
    const Rgb metal = principled(gold, 1, 0.5).bsdf(hit).ambient_reflectance();
    EXPECT_NEAR(metal.b, gold.b, 1e-12);
    // F₀ + (1 − F₀)² ρ, as plastic: 0.04 + 0.96² for a white base.
    const Rgb white = principled(Rgb(1.0), 0, 0.5).bsdf(hit).ambient_reflectance();
    EXPECT_NEAR(white.g, 0.04 + 0.96 * 0.96, 1e-12);
}

TEST(Principled, EmitsNothing) {
    const Hit hit = test_hit();
    EXPECT_TRUE(principled(Rgb(1.0), 0.5, 0.5).emitted(hit, hit.normal).is_black());
}

}  // namespace
}  // namespace glint
