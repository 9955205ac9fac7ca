// Every BSDF against its own contract: sampling distributed as pdf() says (χ²), sample() agreeing with
// evaluate() and pdf(), energy conservation (white furnace), reciprocity, both sides of the surface, and
// the world-space values agreeing with the shading frame's however that frame is turned.
#include <gtest/gtest.h>

#include <functional>
#include <memory>

#include "glint/material/dielectric.hpp"
#include "glint/material/fuzzy_metal.hpp"
#include "glint/material/matte.hpp"
#include "glint/material/metal.hpp"
#include "glint/material/mirror.hpp"
#include "glint/material/phong.hpp"
#include "glint/material/plastic.hpp"
#include "glint/material/principled.hpp"
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
        // Principled (metallic, roughness): the dielectric, the metal and a blend, smooth to rough.
        {"PrincipledDielectric05",
         [] { return std::make_unique<Principled>(constant(0.7), constant(0), constant(0.5), 1.5, 1.0); }},
        {"PrincipledMetal03",
         [] {
             return std::make_unique<Principled>(std::make_shared<ConstantTexture>(Rgb(0.9, 0.6, 0.3)),
                                                 constant(1), constant(0.3), 1.5, 1.0);
         }},
        {"PrincipledHalfMetal07",
         [] { return std::make_unique<Principled>(constant(0.5), constant(0.5), constant(0.7), 1.5, 1.0); }},
        {"PrincipledDielectric10",
         [] { return std::make_unique<Principled>(constant(0.3), constant(0), constant(1.0), 2.0, 0.5); }},
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
    const Bsdf bsdf = material->bsdf(hit);
    int non_delta = 0;
    for (const double c : kViewCosines) {
        const Vec3 wo = direction_at(hit, c, 2.1);
        for (std::uint32_t i = 0; i < 2000; ++i) {
            const auto s = bsdf.sample(wo, test_point(5, i));
            if (!s) {
                continue;
            }
            EXPECT_NEAR(length(s->wi), 1.0, 1e-12);
            if (s->delta) {
                EXPECT_TRUE(bsdf.evaluate(wo, s->wi).is_black() || GetParam().name == "Plastic");
                continue;
            }
            ++non_delta;
            ASSERT_GT(s->pdf, 0);
            const double pdf = bsdf.pdf(wo, s->wi);
            EXPECT_NEAR(s->pdf, pdf, 1e-9 * pdf);
            const Rgb f = bsdf.evaluate(wo, s->wi);
            EXPECT_NEAR(s->f.r, f.r, 1e-9 * f.max_component());
            EXPECT_NEAR(s->f.g, f.g, 1e-9 * f.max_component());
            EXPECT_NEAR(s->f.b, f.b, 1e-9 * f.max_component());
            // Reflection only: wi on wo's side of the surface.
            EXPECT_GT(dot(hit.shading_normal, wo) * dot(hit.shading_normal, s->wi), 0);
        }
    }
    EXPECT_GT(non_delta, 1000);
}

// Each sample's weight, in closed form where the material has one (Lambert's ρ, a mirror's
// reflectance, glass's (n1/n2)²), is its f · |cos θi| / pdf: the path tracer carries its throughput on
// by the weight alone.
void expect_weights_are_f_cos_over_pdf(const Material& material) {
    const Hit hit = test_hit();
    const Bsdf bsdf = material.bsdf(hit);
    int samples = 0;
    for (const double c : kViewCosines) {
        const Vec3 wo = direction_at(hit, c, 1.3);
        for (std::uint32_t i = 0; i < 500; ++i) {
            const auto s = bsdf.sample(wo, test_point(7, i));
            if (!s || !(s->pdf > 0)) {
                continue;
            }
            ++samples;
            const Rgb expected = s->f * (std::abs(dot(hit.shading_normal, s->wi)) / s->pdf);
            const double tolerance = 1e-12 * expected.max_component();
            EXPECT_NEAR(s->weight.r, expected.r, tolerance) << "cos θo = " << c << ", sample " << i;
            EXPECT_NEAR(s->weight.g, expected.g, tolerance) << "cos θo = " << c << ", sample " << i;
            EXPECT_NEAR(s->weight.b, expected.b, tolerance) << "cos θo = " << c << ", sample " << i;
        }
    }
    EXPECT_GT(samples, 1000);
}

TEST_P(ScatteringBsdf, SampleWeightIsFCosOverPdf) {
    expect_weights_are_f_cos_over_pdf(*GetParam().make());
}

TEST_P(ScatteringBsdf, IsReciprocal) {
    const auto material = GetParam().make();
    const Hit hit = test_hit();
    const Bsdf bsdf = material->bsdf(hit);
    int scattering_pairs = 0;
    for (std::uint32_t i = 0; i < 500; ++i) {
        const SampleKey key{3, i, 0, 0};
        const double side = i % 2 == 0 ? 1 : -1;  // both sides of the surface
        const Vec3 a = direction_at(hit, side * (0.02 + 0.98 * key.uniform(0)), 2 * kPi * key.uniform(1));
        const Vec3 b = direction_at(hit, side * (0.02 + 0.98 * key.uniform(2)), 2 * kPi * key.uniform(3));
        const Rgb fab = bsdf.evaluate(a, b), fba = bsdf.evaluate(b, a);
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

// A rotation by `angle` about the unit `axis` (Rodrigues' formula).
struct Rotation {
    Vec3 axis;
    double angle;
    Vec3 operator()(const Vec3& v) const {
        const double c = std::cos(angle), s = std::sin(angle);
        return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c));
    }
    Vec3 inverse(const Vec3& v) const { return Rotation{axis, -angle}(v); }
};

// Rotations that take +z to shading normals all around the sphere: tilted, sideways, exactly −z (where
// the frame construction switches branch) and next to it.
const Rotation kRotations[] = {
    {normalize(Vec3{1, 2, 3}), 2.0},      {Vec3{1, 0, 0}, kPi / 2},    {Vec3{1, 0, 0}, kPi},
    {normalize(Vec3{0.3, -0.2, 1}), 0.7}, {Vec3{0, 1, 0}, kPi - 1e-3}, {normalize(Vec3{-1, 1, 0}), 2.5},
};

// The hit whose shading frame is the world's axes: there world and local coordinates are the same.
Hit canonical_hit() {
    return test_hit(Vec3{0, 0, 1});
}

TEST(ShadingFrame, TheCanonicalHitsFrameIsTheWorldsAxes) {
    const Bsdf bsdf = Matte(Rgb(0.5)).bsdf(canonical_hit());
    EXPECT_EQ(bsdf.frame().s, Vec3(1, 0, 0));
    EXPECT_EQ(bsdf.frame().t, Vec3(0, 1, 0));
    EXPECT_EQ(bsdf.frame().n, Vec3(0, 0, 1));
}

// The same pair of directions relative to the surface, turned with it, gives the same f and pdf: the
// world-space BSDF at the turned hit against the local one (at the canonical hit). A sample's f and pdf
// at the turned hit are the canonical ones of its direction turned back.
TEST_P(ScatteringBsdf, WorldValuesAgreeWithTheLocalFrameForRotatedShadingFrames) {
    const auto material = GetParam().make();
    const Bsdf local = material->bsdf(canonical_hit());
    int nonzero = 0;
    for (const Rotation& rotation : kRotations) {
        const Bsdf bsdf = material->bsdf(test_hit(rotation(Vec3{0, 0, 1})));
        for (std::uint32_t i = 0; i < 400; ++i) {
            const SampleKey key{21, i, 0, 0};
            const double side = i % 2 == 0 ? 1 : -1;
            const Vec3 wo_local =
                direction_at(canonical_hit(), side * (0.02 + 0.98 * key.uniform(0)), 7 * key.uniform(1));
            // Mostly on wo's side (reflection); every fourth on the other (where f and pdf are 0).
            const double wi_side = i % 4 == 3 ? -side : side;
            const Vec3 wi_local =
                direction_at(canonical_hit(), wi_side * (0.02 + 0.98 * key.uniform(2)), 7 * key.uniform(3));
            const Vec3 wo = rotation(wo_local), wi = rotation(wi_local);
            const Rgb f = bsdf.evaluate(wo, wi), expected = local.evaluate_local(wo_local, wi_local);
            const double tolerance = 1e-9 * std::max(1.0, expected.max_component());
            EXPECT_NEAR(f.r, expected.r, tolerance);
            EXPECT_NEAR(f.g, expected.g, tolerance);
            EXPECT_NEAR(f.b, expected.b, tolerance);
            const double pdf = local.pdf_local(wo_local, wi_local);
            EXPECT_NEAR(bsdf.pdf(wo, wi), pdf, 1e-9 * std::max(1.0, pdf));
            nonzero += expected.is_black() ? 0 : 1;

            const auto s = bsdf.sample(wo, test_point(22, i));
            if (!s || s->delta) {
                continue;
            }
            const Vec3 back = rotation.inverse(s->wi);
            const Rgb f_back = local.evaluate_local(wo_local, back);
            EXPECT_NEAR(s->f.g, f_back.g, 1e-9 * std::max(1.0, f_back.g));
            const double pdf_back = local.pdf_local(wo_local, back);
            EXPECT_NEAR(s->pdf, pdf_back, 1e-9 * std::max(1.0, pdf_back));
        }
    }
    EXPECT_GT(nonzero, 1000) << "the test must compare non-zero values";
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
    const Bsdf bsdf = mirror.bsdf(hit);
    for (const double c : kViewCosines) {
        const Vec3 wo = direction_at(hit, c, 0.3);
        const auto s = bsdf.sample(wo, {0.5, 0.5});
        ASSERT_TRUE(s && s->delta);
        // Paper eq. 16: the angle of reflection equals the angle of incidence, in the plane of incidence.
        EXPECT_NEAR(dot(s->wi, hit.shading_normal), dot(wo, hit.shading_normal), 1e-12);
        EXPECT_NEAR(dot(cross(wo, s->wi), hit.shading_normal), 0, 1e-12);
        EXPECT_NEAR((s->f * (std::abs(dot(hit.shading_normal, s->wi)) / s->pdf)).r, 1.0, 1e-12);
        EXPECT_EQ(bsdf.pdf(wo, s->wi), 0);
        EXPECT_TRUE(bsdf.evaluate(wo, s->wi).is_black());
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
        const Bsdf bsdf = m->bsdf(hit);
        for (std::uint32_t i = 0; i < 200; ++i) {
            const Vec3 wo = direction_at(hit, i % 2 ? 0.6 : -0.6, 0.01 * i);
            const auto s = bsdf.sample(wo, test_point(9, i));
            ASSERT_TRUE(s);
            EXPECT_TRUE(s->delta);
            EXPECT_TRUE(bsdf.evaluate(wo, s->wi).is_black());
            EXPECT_EQ(bsdf.pdf(wo, s->wi), 0);
        }
    }
}

TEST(DeltaLobes, SampleWeightIsFCosOverPdf) {
    // Glass reflects and refracts (from inside, beyond the critical angle too); the plastic's coat
    // and its diffuse base; a fuzzy metal sharp and fuzzy.
    const Dielectric glass(1.5, Rgb());
    const Mirror mirror(std::make_shared<ConstantTexture>(Rgb(0.8, 0.5, 0.2)));
    const Metal smooth(constant(0.8), 0.01);
    const FuzzyMetal sharp_fuzzy(constant(0.7), 0);
    const FuzzyMetal fuzzy(constant(0.7), 0.4);
    const Plastic plastic(constant(0.5), 1.5);
    for (const Material* m :
         std::initializer_list<const Material*>{&glass, &mirror, &smooth, &sharp_fuzzy, &fuzzy, &plastic}) {
        expect_weights_are_f_cos_over_pdf(*m);
    }
}

// Delta lobes depend on the normal only (not on the frame's tangents): at a turned hit a sample is the
// canonical sample turned, with the same f and pdf, for the same random numbers.
TEST(DeltaLobes, SamplesTurnWithTheShadingFrame) {
    const Dielectric glass(1.5, Rgb());
    const Mirror mirror(constant(0.8));
    const Metal smooth(constant(0.8), 0.01);
    const FuzzyMetal sharp_fuzzy(constant(0.7), 0);
    const Plastic plastic(constant(0.5), 1.5);  // its coat, for u.x below the coat's probability
    for (const Material* m :
         std::initializer_list<const Material*>{&glass, &mirror, &smooth, &sharp_fuzzy, &plastic}) {
        const Bsdf local = m->bsdf(canonical_hit());
        int delta_samples = 0;
        for (const Rotation& rotation : kRotations) {
            const Bsdf bsdf = m->bsdf(test_hit(rotation(Vec3{0, 0, 1})));
            for (std::uint32_t i = 0; i < 100; ++i) {
                // Outside and inside, some beyond glass's critical angle from inside.
                const double c = (i % 2 == 0 ? 1 : -1) * (0.05 + 0.9 * i / 100.0);
                const Vec3 wo_local = direction_at(canonical_hit(), c, 0.37 * i);
                const Point2 u{i % 3 == 0 ? 0.0 : 0.9999, 0.5};
                const auto expected = local.sample_local(wo_local, u);
                const auto s = bsdf.sample(rotation(wo_local), u);
                ASSERT_EQ(s.has_value(), expected.has_value());
                if (!s || !expected->delta) {
                    continue;
                }
                ++delta_samples;
                EXPECT_TRUE(s->delta);
                EXPECT_LT(length(s->wi - rotation(expected->wi)), 1e-12);
                EXPECT_NEAR(s->pdf, expected->pdf, 1e-12);
                EXPECT_NEAR(s->f.g, expected->f.g, 1e-12 * std::max(1.0, expected->f.g));
            }
        }
        EXPECT_GT(delta_samples, 100);
    }
}

}  // namespace
}  // namespace glint
