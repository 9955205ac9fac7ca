// Ray Tracing in One Weekend's lobes: fuzzy-metal (the mirror direction perturbed by fuzz × a random
// point in the unit ball or on the unit sphere) and the dielectric's Schlick reflect/refract choice, against
// the book's definitions, and furnaces that show the fuzzy lobe neither creates light nor differs from a
// mirror at fuzz 0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "glint/material/dielectric.hpp"
#include "glint/material/fresnel.hpp"
#include "glint/material/fuzzy_metal.hpp"
#include "glint/material/mirror.hpp"
#include "integrator/radiance_util.hpp"
#include "material/bsdf_checks.hpp"

namespace glint {
namespace {

using testing::direction_at;
using testing::mirror_direction;
using testing::test_hit;
using testing::test_point;

FuzzyMetal fuzzy(double albedo, double fuzz,
                 FuzzyMetal::Perturbation perturbation = FuzzyMetal::Perturbation::Ball) {
    return FuzzyMetal(std::make_shared<ConstantTexture>(Rgb(albedo)), fuzz, perturbation);
}

double angle_between(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(dot(normalize(a), normalize(b)), -1.0, 1.0));
}

TEST(FuzzyMetal, FuzzZeroReflectsIntoTheMirrorDirectionWithWeightAlbedo) {
    const Hit hit = test_hit();
    const FuzzyMetal metal = fuzzy(0.6, 0);
    for (std::uint32_t i = 0; i < 64; ++i) {
        const Vec3 wo = direction_at(hit, 0.05 + 0.9 * (i % 8) / 7.0, 0.8 * i);
        const auto s = metal.bsdf(hit).sample(wo, test_point(1, i));
        ASSERT_TRUE(s);
        EXPECT_LT(length(s->wi - mirror_direction(hit, wo)), 1e-12);
        EXPECT_TRUE(s->delta);
        EXPECT_NEAR(s->f.g * std::abs(dot(hit.shading_normal, s->wi)) / s->pdf, 0.6, 1e-12);
    }
}

TEST(FuzzyMetal, SamplesLieInTheConeOfHalfAngleArcsinFuzzAboutTheMirrorDirection) {
    const Hit hit = test_hit();
    for (const double fuzz : {0.1, 0.5, 0.9}) {
        const FuzzyMetal metal = fuzzy(1, fuzz);
        const double half_angle = std::asin(fuzz);
        // At normal incidence the whole cone lies above the surface: samples fill it to its edge.
        double widest = 0;
        for (std::uint32_t i = 0; i < 4096; ++i) {
            const auto s = metal.bsdf(hit).sample(hit.shading_normal, test_point(2, i));
            ASSERT_TRUE(s);
            EXPECT_NEAR(length(s->wi), 1, 1e-12);
            const double angle = angle_between(s->wi, hit.shading_normal);
            EXPECT_LE(angle, half_angle + 1e-9) << fuzz;
            widest = std::max(widest, angle);
        }
        EXPECT_GT(widest, 0.97 * half_angle) << fuzz;
        // From other directions the same cone about R, seen from either side of the surface.
        for (const double side : {1.0, -1.0}) {
            for (std::uint32_t i = 0; i < 512; ++i) {
                const Vec3 wo = side * direction_at(hit, 0.1 + 0.8 * (i % 16) / 15.0, 0.37 * i);
                const auto s = metal.bsdf(hit).sample(wo, test_point(3, i));
                if (s) {
                    EXPECT_LE(angle_between(s->wi, mirror_direction(hit, wo)), half_angle + 1e-9);
                    EXPECT_GT(dot(s->wi, side * hit.shading_normal), 0);
                }
            }
        }
    }
}

TEST(FuzzyMetal, DirectionsPerturbedBelowTheSurfaceAreAbsorbed) {
    // Near grazing incidence much of the cone lies below the surface: those samples end the path.
    const Hit hit = test_hit();
    const FuzzyMetal metal = fuzzy(1, 0.8, FuzzyMetal::Perturbation::Sphere);
    const Vec3 wo = direction_at(hit, 0.1, 1.0);
    const Frame frame = Frame::from_normal(hit.shading_normal);
    int absorbed = 0;
    const int n = 2000;
    for (std::uint32_t i = 0; i < n; ++i) {
        const Point2 u = test_point(4, i);
        const auto s = metal.bsdf(hit).sample(wo, u);
        // The book's rule, recomputed: R + fuzz · (uniform unit vector), absorbed if not above. The
        // unit vector's coordinates are taken in the shading frame (the book's are in world axes).
        const double z = 1 - 2 * u.x, r = std::sqrt(1 - z * z), phi = 2 * kPi * u.y;
        const Vec3 scattered =
            mirror_direction(hit, wo) + 0.8 * frame.to_world(Vec3{r * std::cos(phi), r * std::sin(phi), z});
        EXPECT_EQ(s.has_value(), dot(scattered, hit.shading_normal) > 0) << i;
        absorbed += s ? 0 : 1;
    }
    EXPECT_GT(absorbed, n / 10);
    EXPECT_LT(absorbed, n);
}

TEST(FuzzyMetalFurnace, AWhiteSphereOfFuzzOneKeepsTheShareOfPerturbationsAboveItsSurface) {
    // Seen head-on at a point whose normal makes cos θ = c with the view, the mirror direction R has
    // R·N = c, and R + s is above the surface when s·N > −c. For s uniform in the unit ball s·N has
    // density 3(1 − t²)/4, so P = (2 + 3c − c³)/4; on the unit sphere it is uniform: P = (1 + c)/2.
    // Under a white sky a white sphere shows exactly P (the rest is absorbed).
    for (const bool ball : {true, false}) {
        const std::string yaml =
            std::string("render: {width: 64, height: 1, samples: 4096, max_depth: 50, integrator: path}\n") +
            "camera: {type: orthographic, eye: [0, 0, 5], look_at: [0, 0, 0], up: [0, 1, 0], height: "
            "0.03125}\n"
            "objects: [{type: sphere, radius: 1, material: {type: fuzzy-metal, albedo: 1, fuzz: 1, "
            "perturbation: " +
            (ball ? "ball" : "sphere") + "}}]\nlights: [{type: environment, radiance: 1}]\n";
        const Film film = test::render_film(test::scene_from_yaml(yaml));
        // The film is 2 wide (64 pixels of 1/32): pixel x covers [x/32 − 1, (x + 1)/32 − 1).
        for (const int x : {32, 40, 48, 54, 58}) {
            double expected = 0;  // the mean of P over the pixel's width, by the midpoint rule
            for (int k = 0; k < 64; ++k) {
                const double px = (x + (k + 0.5) / 64) / 32 - 1;
                const double c = std::sqrt(1 - px * px);
                expected += (ball ? (2 + 3 * c - c * c * c) / 4 : (1 + c) / 2) / 64;
            }
            // Each sample is 1 or 0 (no roulette: the throughput stays 1): four binomial standard errors.
            const double tolerance = 4 * std::sqrt(expected * (1 - expected) / 4096) + 1e-9;
            EXPECT_NEAR(film.pixel(x, 0).g, expected, tolerance)
                << (ball ? "ball" : "sphere") << ", pixel " << x;
        }
    }
}

TEST(FuzzyMetal, EvaluateAndPdfAreZeroLikeADeltaLobe) {
    const Hit hit = test_hit();
    const FuzzyMetal metal = fuzzy(1, 0.5);
    const Vec3 wo = direction_at(hit, 0.7, 0.3);
    const Vec3 r = mirror_direction(hit, wo);
    EXPECT_TRUE(metal.bsdf(hit).evaluate(wo, r).is_black());
    EXPECT_EQ(metal.bsdf(hit).pdf(wo, r), 0);
    EXPECT_TRUE(metal.random_delta_direction());
    EXPECT_FALSE(fuzzy(1, 0).random_delta_direction());
}

TEST(Schlick, NormalIncidenceGivesR0AndGrazingGivesOne) {
    EXPECT_NEAR(fresnel_r0(1, 1.5), 0.04, 1e-15);
    EXPECT_NEAR(schlick(1.0, fresnel_r0(1, 1.5)), 0.04, 1e-15);
    EXPECT_NEAR(schlick(0.0, fresnel_r0(1, 1.5)), 1.0, 1e-15);
    EXPECT_NEAR(schlick(0.5, 0.04), 0.04 + 0.96 / 32, 1e-15);
}

TEST(Schlick, TheDielectricReflectsWithSchlicksProbability) {
    const Hit hit = test_hit();
    const Dielectric schlick_glass(1.5, Rgb(), Dielectric::Fresnel::Schlick);
    const Dielectric exact_glass(1.5, Rgb(), Dielectric::Fresnel::Exact);
    // From outside (n₁ = 1) and from inside at an angle without total internal reflection; the book's
    // cosine is wo's own.
    for (const double side : {1.0, -1.0}) {
        for (const double cos_o : {0.95, 0.8}) {
            const Vec3 wo = side * direction_at(hit, cos_o, 0.4);
            const double r0 = fresnel_r0(1, 1.5);
            const double expected = schlick(cos_o, r0);
            const Vec3 mirror = mirror_direction(hit, wo);
            const int n = 1000;  // stratified u.x: the share of reflections is R within 1/n
            int reflected = 0;
            for (int i = 0; i < n; ++i) {
                const auto s = schlick_glass.bsdf(hit).sample(wo, {(i + 0.5) / n, 0.5});
                ASSERT_TRUE(s);
                const bool is_reflection = length(s->wi - mirror) < 1e-12;
                reflected += is_reflection ? 1 : 0;
                EXPECT_NEAR(s->pdf, is_reflection ? expected : 1 - expected, 1e-12);
            }
            EXPECT_NEAR(reflected / double(n), expected, 1.0 / n) << side << " " << cos_o;
            // The option changes the probability: exact Fresnel differs from Schlick here.
            const auto exact = exact_glass.bsdf(hit).sample(wo, {0, 0.5});
            ASSERT_TRUE(exact);
            EXPECT_GT(std::abs(exact->pdf - expected), 1e-5);
        }
    }
}

TEST(Schlick, SmallptsVariantTakesTheCosineOnTheOutside) {
    // smallpt: c = 1 − (into ? cos θi : cos θt), θt the refracted direction's angle in the air.
    const Hit hit = test_hit();
    const Dielectric glass(1.5, Rgb(), Dielectric::Fresnel::SchlickOutside);
    const double r0 = fresnel_r0(1, 1.5);
    const Vec3 from_outside = direction_at(hit, 0.8, 0.4);
    const auto a = glass.bsdf(hit).sample(from_outside, {0, 0.5});
    ASSERT_TRUE(a);
    EXPECT_NEAR(a->pdf, schlick(0.8, r0), 1e-12);
    const Vec3 from_inside = -direction_at(hit, 0.8, 0.4);
    const double sin_t = 1.5 * std::sqrt(1 - 0.8 * 0.8);  // Snell into air
    const double cos_t = std::sqrt(1 - sin_t * sin_t);
    const auto b = glass.bsdf(hit).sample(from_inside, {0, 0.5});
    ASSERT_TRUE(b);
    EXPECT_NEAR(b->pdf, schlick(cos_t, r0), 1e-12);
    EXPECT_GT(std::abs(b->pdf - schlick(0.8, r0)), 1e-2);  // not RTIOW's rule
}

TEST(Schlick, TotalInternalReflectionAlwaysReflects) {
    const Hit hit = test_hit();
    const Dielectric glass(1.5, Rgb(), Dielectric::Fresnel::Schlick);
    const Vec3 wo = -direction_at(hit, 0.3, 0.4);  // inside, beyond the critical angle (cos 0.745)
    for (const double ux : {0.0, 0.5, 1 - 0x1p-53}) {
        const auto s = glass.bsdf(hit).sample(wo, {ux, 0.5});
        ASSERT_TRUE(s);
        EXPECT_LT(length(s->wi - mirror_direction(hit, wo)), 1e-12);
        EXPECT_EQ(s->pdf, 1);
    }
}

std::string sphere_under_sky(const std::string& integrator, const std::string& material,
                             const std::string& sky) {
    return "render: {width: 16, height: 16, samples: 8, max_depth: 50, integrator: " + integrator +
           "}\ncamera: {eye: [0, 0, 4], look_at: [0, 0, 0], fov: 30}\n"
           "objects:\n  - {type: sphere, radius: 1, material: " +
           material +
           "}\n  - {type: sphere, center: [0, -101, 0], radius: 100, material: {type: matte, albedo: 0.5}}\n"
           "lights: [{type: environment, radiance: " +
           sky + "}]\n";
}

TEST(FuzzyMetalFurnace, AWhiteFuzzySphereUnderAUniformSkyNeverExceedsTheSky) {
    for (const double fuzz : {0.3, 1.0}) {
        const std::string material = "{type: fuzzy-metal, albedo: 1, fuzz: " + std::to_string(fuzz) + "}";
        // Whitted follows one random direction per sample, without roulette: each sample is exactly
        // the sky (1) or absorbed (0), so no pixel exceeds 1 (splitting into two "lobes" would give 2).
        const std::string yaml =
            "render: {width: 16, height: 16, samples: 8, max_depth: 50, integrator: whitted}\n"
            "camera: {eye: [0, 0, 4], look_at: [0, 0, 0], fov: 30}\n"
            "objects: [{type: sphere, radius: 1, material: " +
            material + "}]\nlights: [{type: environment, radiance: 1}]\n";
        const Film whitted = test::render_film(test::scene_from_yaml(yaml));
        double darkest = 1;
        for (int y = 0; y < 16; ++y) {
            for (int x = 0; x < 16; ++x) {
                EXPECT_LE(whitted.pixel(x, y).g, 1 + 1e-12) << x << ", " << y;
                darkest = std::min(darkest, whitted.pixel(x, y).g);
            }
        }
        EXPECT_LT(darkest, 0.99);  // the sphere's rim absorbs what it perturbs below its surface
        EXPECT_NEAR(whitted.pixel(8, 8).g, 1, 1e-12);  // the centre never does (cone above the surface)
        // The path tracer with Russian roulette: the same in the mean, never above the sky.
        std::string path_yaml = yaml;
        path_yaml.replace(path_yaml.find("whitted"), 7, "path");
        const Film path = test::render_film(test::scene_from_yaml(path_yaml));
        const test::RegionMean mean = test::region_mean(path, 0, 0, 16, 16);
        EXPECT_LE(mean.mean, 1 + 4 * mean.standard_error);
    }
}

TEST(FuzzyMetalFurnace, FuzzZeroRendersExactlyAsTheMirror) {
    // Under a gradient sky with a matte floor (lit by next-event estimation), with both integrators:
    // the fuzz-0 lobe draws the same numbers and gives the same weights as `mirror`.
    const std::string sky = "{type: gradient, bottom: [1, 1, 1], top: [0.5, 0.7, 1.0]}";
    for (const std::string integrator : {"path", "whitted"}) {
        const Film fuzzy_film = test::render_film(test::scene_from_yaml(
            sphere_under_sky(integrator, "{type: fuzzy-metal, albedo: [0.7, 0.6, 0.5], fuzz: 0}", sky)));
        const Film mirror_film = test::render_film(test::scene_from_yaml(
            sphere_under_sky(integrator, "{type: mirror, reflectance: [0.7, 0.6, 0.5]}", sky)));
        for (int y = 0; y < 16; ++y) {
            for (int x = 0; x < 16; ++x) {
                const Rgb a = fuzzy_film.pixel(x, y), b = mirror_film.pixel(x, y);
                EXPECT_NEAR(a.r, b.r, 1e-12) << integrator << " " << x << ", " << y;
                EXPECT_NEAR(a.b, b.b, 1e-12) << integrator << " " << x << ", " << y;
            }
        }
    }
}

}  // namespace
}  // namespace glint
