// Every BSDF against its own contract: sampling distributed as pdf() says (χ²), sample() agreeing with
// evaluate() and pdf(), energy conservation (white furnace), reciprocity, and both sides of the surface.
#include <gtest/gtest.h>

#include <functional>
#include <memory>

#include "glint/material/dielectric.hpp"
#include "glint/material/matte.hpp"
#include "glint/material/metal.hpp"
#include "glint/material/mirror.hpp"
#include "glint/material/phong.hpp"
#include "glint/material/plastic.hpp"
#include "material/bsdf_checks.hpp"

namespace glint {
namespace {

using testing::chi2_test;
using testing::direction_at;
using testing::estimate_albedo;
using testing::test_hit;
using testing::test_point;

std::shared_ptr<const Texture> constant(double v) {
    return std::make_shared<ConstantTexture>(Rgb(v));
}

struct BsdfCase {
    std::string name;
    std::function<std::unique_ptr<Material>()> make;
};
void PrintTo(const BsdfCase& c, std::ostream* os) {
    *os << c.name;
}

std::vector<BsdfCase> scattering_cases() {
    return {
        {"Matte", [] { return std::make_unique<Matte>(Rgb(0.7)); }},
        {"PhongMixed", [] { return std::make_unique<Phong>(constant(0.5), constant(0.4), 20.0); }},
        {"PhongGlossyOnly", [] { return std::make_unique<Phong>(constant(0.0), constant(1.0), 8.0); }},
        {"Plastic", [] { return std::make_unique<Plastic>(constant(0.6), 1.5); }},
        {"MetalRough03", [] { return std::make_unique<Metal>(constant(0.9), 0.3); }},
        {"MetalRough07", [] { return std::make_unique<Metal>(constant(0.9), 0.7); }},
    };
}

class ScatteringBsdf : public ::testing::TestWithParam<BsdfCase> {};

// Viewing directions: near the normal, oblique, grazing, and from the back side of the surface.
const double kViewCosines[] = {0.95, 0.5, 0.15, -0.6};

TEST_P(ScatteringBsdf, SamplingMatchesPdfByChiSquare) {
    const auto material = GetParam().make();
    const Hit hit = test_hit();
    std::uint64_t seed = 11;
    for (const double c : kViewCosines) {
        const Vec3 wo = direction_at(hit, c, 0.7);
        const auto outcome = chi2_test(*material, hit, wo, 120000, seed++);
        EXPECT_FALSE(outcome.impossible) << "cos θo = " << c << ": " << outcome.report;
        EXPECT_LT(outcome.statistic, outcome.critical) << "cos θo = " << c << ": " << outcome.report;
    }
}

TEST_P(ScatteringBsdf, SampleAgreesWithEvaluateAndPdf) {
    const auto material = GetParam().make();
    const Hit hit = test_hit();
    int non_delta = 0;
    for (const double c : kViewCosines) {
        const Vec3 wo = direction_at(hit, c, 2.1);
        for (std::uint32_t i = 0; i < 2000; ++i) {
            const auto s = material->sample(hit, wo, test_point(5, i));
            if (!s) {
                continue;
            }
            EXPECT_NEAR(length(s->wi), 1.0, 1e-12);
            if (s->delta) {
                EXPECT_TRUE(material->evaluate(hit, wo, s->wi).is_black() || GetParam().name == "Plastic");
                continue;
            }
            ++non_delta;
            ASSERT_GT(s->pdf, 0);
            const double pdf = material->pdf(hit, wo, s->wi);
            EXPECT_NEAR(s->pdf, pdf, 1e-9 * pdf);
            const Rgb f = material->evaluate(hit, wo, s->wi);
            EXPECT_NEAR(s->f.r, f.r, 1e-9 * f.max_component());
            EXPECT_NEAR(s->f.g, f.g, 1e-9 * f.max_component());
            EXPECT_NEAR(s->f.b, f.b, 1e-9 * f.max_component());
            // Reflection only: wi on wo's side of the surface.
            EXPECT_GT(dot(hit.shading_normal, wo) * dot(hit.shading_normal, s->wi), 0);
        }
    }
    EXPECT_GT(non_delta, 1000);
}

TEST_P(ScatteringBsdf, IsReciprocal) {
    const auto material = GetParam().make();
    const Hit hit = test_hit();
    int scattering_pairs = 0;
    for (std::uint32_t i = 0; i < 500; ++i) {
        const SampleKey key{3, i, 0, 0};
        const double side = i % 2 == 0 ? 1 : -1;  // both sides of the surface
        const Vec3 a = direction_at(hit, side * (0.02 + 0.98 * key.uniform(0)), 2 * kPi * key.uniform(1));
        const Vec3 b = direction_at(hit, side * (0.02 + 0.98 * key.uniform(2)), 2 * kPi * key.uniform(3));
        const Rgb fab = material->evaluate(hit, a, b), fba = material->evaluate(hit, b, a);
        const double scale = std::max(1e-300, fab.max_component());
        EXPECT_NEAR(fab.r, fba.r, 1e-9 * scale);
        EXPECT_NEAR(fab.g, fba.g, 1e-9 * scale);
        EXPECT_NEAR(fab.b, fba.b, 1e-9 * scale);
        scattering_pairs += fab.is_black() ? 0 : 1;
    }
    EXPECT_GT(scattering_pairs, 100) << "the test must compare non-zero values";
}

TEST_P(ScatteringBsdf, ReflectsNoMoreThanItReceives) {
    const auto material = GetParam().make();
    const Hit hit = test_hit();
    for (const double c : kViewCosines) {
        const auto e = estimate_albedo(*material, hit, direction_at(hit, c, 1.0), 40000, 17);
        EXPECT_LE(e.mean, 1 + 4 * e.standard_error) << "cos θo = " << c;
        EXPECT_GT(e.mean, 0.05) << "cos θo = " << c;
    }
}

INSTANTIATE_TEST_SUITE_P(Material, ScatteringBsdf, ::testing::ValuesIn(scattering_cases()),
                         [](const auto& test_info) { return test_info.param.name; });

// White furnace: with albedo 1, each BSDF's directional albedo, estimated from its own samples.
TEST(WhiteFurnace, MatteReflectsExactlyAll) {
    const Matte matte(Rgb(1.0));
    const Hit hit = test_hit();
    for (const double c : kViewCosines) {
        const auto e = estimate_albedo(matte, hit, direction_at(hit, c, 0.3), 4000, 1);
        EXPECT_NEAR(e.mean, 1.0, 1e-12);
    }
}

TEST(WhiteFurnace, MirrorReflectsExactlyAll) {
    const Mirror mirror(constant(1.0));
    const Hit hit = test_hit();
    for (const double c : kViewCosines) {
        const Vec3 wo = direction_at(hit, c, 0.3);
        const auto s = mirror.sample(hit, wo, {0.5, 0.5});
        ASSERT_TRUE(s && s->delta);
        // Paper eq. 16: the angle of reflection equals the angle of incidence, in the plane of incidence.
        EXPECT_NEAR(dot(s->wi, hit.shading_normal), dot(wo, hit.shading_normal), 1e-12);
        EXPECT_NEAR(dot(cross(wo, s->wi), hit.shading_normal), 0, 1e-12);
        EXPECT_NEAR((s->f * (std::abs(dot(hit.shading_normal, s->wi)) / s->pdf)).r, 1.0, 1e-12);
        EXPECT_EQ(mirror.pdf(hit, wo, s->wi), 0);
        EXPECT_TRUE(mirror.evaluate(hit, wo, s->wi).is_black());
    }
}

TEST(WhiteFurnace, PhongWithDiffuseOneReflectsAllAndLobeLosesOnlyBelowTheHorizon) {
    const Hit hit = test_hit();
    const Phong diffuse_only(constant(1.0), constant(0.0), 10.0);
    EXPECT_NEAR(estimate_albedo(diffuse_only, hit, direction_at(hit, 0.7, 0), 4000, 2).mean, 1.0, 1e-12);
    // The normalised lobe alone reflects ks · ∫ (n+2)/(2π) cosⁿα cos θ dω: at normal incidence that is
    // exactly ks (the lobe is symmetric about the normal), and less towards grazing angles.
    const Phong lobe_only(constant(0.0), constant(1.0), 30.0);
    const auto normal = estimate_albedo(lobe_only, hit, hit.shading_normal, 40000, 3);
    EXPECT_NEAR(normal.mean, 1.0, 4 * normal.standard_error + 1e-3);
    const auto grazing = estimate_albedo(lobe_only, hit, direction_at(hit, 0.1, 0), 40000, 3);
    EXPECT_LT(grazing.mean, normal.mean);
}

TEST(WhiteFurnace, SmoothMetalOfReflectanceOneReflectsAll) {
    const Metal metal(constant(1.0), 0.0);
    const Hit hit = test_hit();
    EXPECT_TRUE(metal.is_mirror());
    const auto e = estimate_albedo(metal, hit, direction_at(hit, 0.4, 0), 100, 1);
    EXPECT_NEAR(e.mean, 1.0, 1e-12);
}

TEST(WhiteFurnace, RoughMetalLosesLittleAtModerateRoughness) {
    // Single-scattering GGX at α = 0.09 loses well under 2 % at normal incidence.
    const Metal metal(constant(1.0), 0.3);
    const Hit hit = test_hit();
    const auto e = estimate_albedo(metal, hit, hit.shading_normal, 40000, 4);
    EXPECT_LE(e.mean, 1 + 4 * e.standard_error);
    EXPECT_GT(e.mean, 0.98);
}

TEST(WhiteFurnace, WhitePlasticLosesOnlyTheCoatsInternalReflection) {
    // Estimated albedo = F(θo) + (1 − F(θo)) ∫ (1 − F(θi)) cos θi / π dω: for n = 1.5 the last
    // integral is 1 − (hemispherical Fresnel of glass ≈ 0.092), so about 0.91 + 0.09 F(θo).
    const Plastic plastic(constant(1.0), 1.5);
    const Hit hit = test_hit();
    const auto e = estimate_albedo(plastic, hit, hit.shading_normal, 40000, 6);
    const double f0 = 0.04;
    EXPECT_NEAR(e.mean, f0 + (1 - f0) * (1 - 0.0918), 4 * e.standard_error + 2e-3);
}

TEST(DeltaLobes, EvaluateAndPdfAreZeroForEveryDeltaSample) {
    const Dielectric glass(1.5, Rgb());
    const Mirror mirror(constant(0.8));
    const Metal smooth(constant(0.8), 0.01);
    const Hit hit = test_hit();
    for (const Material* m : std::initializer_list<const Material*>{&glass, &mirror, &smooth}) {
        for (std::uint32_t i = 0; i < 200; ++i) {
            const Vec3 wo = direction_at(hit, i % 2 ? 0.6 : -0.6, 0.01 * i);
            const auto s = m->sample(hit, wo, test_point(9, i));
            ASSERT_TRUE(s);
            EXPECT_TRUE(s->delta);
            EXPECT_TRUE(m->evaluate(hit, wo, s->wi).is_black());
            EXPECT_EQ(m->pdf(hit, wo, s->wi), 0);
        }
    }
}

}  // namespace
}  // namespace glint
