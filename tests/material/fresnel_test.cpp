// Fresnel, Snell and Beer values known from optics, not from the code (errata to paper §VIII).
#include "glint/material/fresnel.hpp"

#include <gtest/gtest.h>

#include "glint/material/dielectric.hpp"
#include "glint/material/material.hpp"
#include "material/bsdf_checks.hpp"

namespace glint {
namespace {

using testing::direction_at;
using testing::test_hit;
using testing::test_point;

TEST(Fresnel, NormalIncidenceOnGlassIsFourPercent) {
    EXPECT_NEAR(fresnel_dielectric(1.0, 1.0, 1.5), 0.04, 1e-15);  // ((n − 1)/(n + 1))² = (0.5/2.5)²
    EXPECT_NEAR(fresnel_dielectric(1.0, 1.5, 1.0), 0.04, 1e-15);  // the same from inside
    EXPECT_NEAR(fresnel_r0(1.0, 1.5), 0.04, 1e-15);
    EXPECT_NEAR(schlick(1.0, 0.04), 0.04, 1e-15);
    EXPECT_NEAR(fresnel_dielectric(1.0, 1.0, 1.333), sqr(0.333 / 2.333), 1e-15);  // water
}

TEST(Fresnel, ExactValuesAtOtherAngles) {
    // Glass at 45° from air, by hand: sin θt = 0.70711/1.5 = 0.47140, cos θt = 0.88192,
    // r_s = (0.70711 − 1.32288)/(0.70711 + 1.32288) = −0.30334, r_p = (1.06066 − 0.88192)/(1.06066 + 0.88192)
    // = 0.09201, R = (r_s² + r_p²)/2 = 0.05024.
    EXPECT_NEAR(fresnel_dielectric(std::cos(radians(45)), 1.0, 1.5), 0.05024, 1e-5);
    // Brewster's angle tan θB = n: p-polarised light is not reflected, so R = r_s²/2.
    const double brewster = std::atan(1.5);
    const double cos_t = std::cos(kPi / 2 - brewster);  // θi + θt = 90° at Brewster's angle
    const double r_s = (std::cos(brewster) - 1.5 * cos_t) / (std::cos(brewster) + 1.5 * cos_t);
    EXPECT_NEAR(fresnel_dielectric(std::cos(brewster), 1.0, 1.5), 0.5 * r_s * r_s, 1e-14);
    // Grazing incidence reflects everything; the exact formula and Schlick agree at the ends.
    EXPECT_NEAR(fresnel_dielectric(1e-9, 1.0, 1.5), 1.0, 1e-8);
    EXPECT_NEAR(schlick(0.0, 0.04), 1.0, 1e-15);
    // A negative cosine means light arriving from the n2 side.
    EXPECT_EQ(fresnel_dielectric(-0.8, 1.0, 1.5), fresnel_dielectric(0.8, 1.5, 1.0));
}

TEST(Fresnel, TotalInternalReflectionBeyondTheCriticalAngle) {
    const double critical = std::asin(1 / 1.5);
    EXPECT_NEAR(degrees(critical), 41.81, 0.01);
    const double before = critical - radians(0.01), after = critical + radians(0.01);
    EXPECT_LT(fresnel_dielectric(std::cos(before), 1.5, 1.0), 1.0);
    EXPECT_EQ(fresnel_dielectric(std::cos(after), 1.5, 1.0), 1.0);
    // refract() per the errata: k < 0 past the critical angle, a direction before it.
    const Vec3 n{0, 0, 1};  // glass below, air above: rays going up leave the glass
    const auto incident = [](double theta) { return Vec3{std::sin(theta), 0, std::cos(theta)}; };
    EXPECT_TRUE(refract(incident(before), n, 1.0, 1.5).has_value());
    EXPECT_FALSE(refract(incident(after), n, 1.0, 1.5).has_value());
    // Just before the critical angle the refracted ray skims the surface (within 2°).
    EXPECT_LT(refract(incident(before), n, 1.0, 1.5)->z, std::sin(radians(2)));
}

TEST(Refract, FollowsSnellsLawOnBothSides) {
    for (int i = 0; i < 200; ++i) {
        const SampleKey key{21, static_cast<std::uint32_t>(i), 0, 0};
        const Vec3 normal = normalize(Vec3{key.uniform(0) - 0.5, key.uniform(1) - 0.5, key.uniform(2) - 0.5});
        const Vec3 incident =
            normalize(Vec3{key.uniform(3) - 0.5, key.uniform(4) - 0.5, key.uniform(5) - 0.5});
        const double n_normal_side = 1.0, n_other = 1.7;
        const auto t = refract(incident, normal, n_normal_side, n_other);
        // The ray travels from the side it comes from: against the normal means from the normal's side.
        const bool from_normal_side = dot(incident, normal) < 0;
        const double n1 = from_normal_side ? n_normal_side : n_other,
                     n2 = from_normal_side ? n_other : n_normal_side;
        const double sin1 = length(cross(incident, normal));
        if (!t) {
            EXPECT_GT(n1 * sin1, n2 * (1 - 1e-12)) << "TIR only when sin θt would exceed 1";
            continue;
        }
        EXPECT_NEAR(length(*t), 1.0, 1e-12);
        const double sin2 = length(cross(*t, normal));
        EXPECT_NEAR(n1 * sin1, n2 * sin2, 1e-12);  // Snell: n₁ sin θ₁ = n₂ sin θ₂
        // It crosses the surface and stays in the plane of incidence.
        EXPECT_GT(dot(*t, normal) * dot(incident, normal), 0);
        EXPECT_NEAR(dot(*t, cross(incident, normal)), 0, 1e-12);
    }
}

TEST(Dielectric, SplitsReflectionAndTransmissionByFresnel) {
    const Dielectric glass(1.5, Rgb());
    const Hit hit = test_hit();
    for (const double c : {0.9, 0.4, -0.95, -0.8}) {  // outside and inside (before the critical angle)
        const Vec3 wo = direction_at(hit, c, 1.3);
        const bool outside = c > 0;
        const double n1 = outside ? 1.0 : 1.5, n2 = outside ? 1.5 : 1.0;
        const double fresnel = fresnel_dielectric(std::abs(c), n1, n2);
        int reflected = 0;
        const int samples = 20000;
        for (int i = 0; i < samples; ++i) {
            const auto s = glass.bsdf(hit).sample(wo, test_point(8, static_cast<std::uint32_t>(i)));
            ASSERT_TRUE(s && s->delta);
            const double cos_i = std::abs(dot(hit.shading_normal, s->wi));
            const double weight = s->f.r * cos_i / s->pdf;
            if (dot(s->wi, hit.shading_normal) * c > 0) {
                ++reflected;
                EXPECT_NEAR(s->pdf, fresnel, 1e-12);
                EXPECT_NEAR(weight, 1.0, 1e-12);
                EXPECT_NEAR(dot(s->wi, hit.shading_normal), c, 1e-12);
            } else {
                EXPECT_NEAR(s->pdf, 1 - fresnel, 1e-12);   // R + T = 1
                EXPECT_NEAR(weight, sqr(n1 / n2), 1e-12);  // radiance scales by (n₁/n₂)²
                EXPECT_NEAR(n1 * length(cross(wo, hit.shading_normal)),
                            n2 * length(cross(s->wi, hit.shading_normal)), 1e-12);
            }
        }
        // The fraction reflected is F, within 4 standard deviations of a binomial.
        const double sigma = std::sqrt(fresnel * (1 - fresnel) / samples);
        EXPECT_NEAR(static_cast<double>(reflected) / samples, fresnel, 4 * sigma + 1e-12) << "cos θo = " << c;
    }
}

TEST(Dielectric, ReflectsEverythingPastTheCriticalAngleFromInside) {
    const Dielectric glass(1.5, Rgb());
    const Hit hit = test_hit();
    const Vec3 wo = direction_at(hit, -std::cos(std::asin(1 / 1.5) + radians(1)), 0.4);
    for (std::uint32_t i = 0; i < 100; ++i) {
        const auto s = glass.bsdf(hit).sample(wo, test_point(4, i));
        ASSERT_TRUE(s);
        EXPECT_EQ(s->pdf, 1.0);
        EXPECT_LT(dot(s->wi, hit.shading_normal), 0);  // stays inside
    }
}

TEST(Dielectric, RadianceFactorsCancelThroughASlab) {
    // Enter a glass slab from air and leave through the parallel face: the path weight is
    // (1 − F₁)(1/1.5)² · (1 − F₂)(1.5)² = (1 − F₁)(1 − F₂), and the ray leaves parallel to how it came.
    const Dielectric glass(1.5, Rgb());
    const Hit top = test_hit(Vec3{0, 0, 1});
    const Hit bottom = test_hit(Vec3{0, 0, -1});
    const Vec3 wo = normalize(Vec3{0.6, 0, 0.8});  // towards the camera, above the slab
    // u.x = 0.999…: transmission whenever F < 0.999.
    const auto in = glass.bsdf(top).sample(wo, {0.9999, 0});
    ASSERT_TRUE(in);
    const auto out =
        glass.bsdf(bottom).sample(-in->wi, {0.9999, 0});  // wo inside the slab at the bottom face
    ASSERT_TRUE(out);
    const double w_in = in->f.r * std::abs(in->wi.z) / in->pdf;
    const double w_out = out->f.r * std::abs(out->wi.z) / out->pdf;
    EXPECT_NEAR(w_in * w_out, 1.0, 1e-12);
    EXPECT_NEAR(length(out->wi - (-wo)), 0.0, 1e-12);
    const double f1 = fresnel_dielectric(0.8, 1.0, 1.5);
    EXPECT_NEAR(in->pdf * out->pdf, sqr(1 - f1), 1e-12);  // Stokes: F is the same both ways across
}

TEST(Dielectric, BeerTransmittanceThroughASlabFromItsAbsorption) {
    // σ = (0.5, 1, 2) per unit; a ray refracted into a slab of thickness 2 at 45° from air travels
    // 2 / cos θt inside, with sin θt = sin 45° / 1.5.
    const Dielectric tinted(1.5, Rgb(0.5, 1.0, 2.0));
    const Rgb sigma = tinted.absorption();
    EXPECT_EQ(sigma, Rgb(0.5, 1.0, 2.0));
    const Hit top = test_hit(Vec3{0, 0, 1});
    const auto in = tinted.bsdf(top).sample(normalize(Vec3{1, 0, 1}), {0.9999, 0});
    ASSERT_TRUE(in);
    const double thickness = 2;
    const double distance = thickness / std::abs(in->wi.z);
    const double cos_t = std::sqrt(1 - sqr(std::sin(radians(45)) / 1.5));
    EXPECT_NEAR(distance, thickness / cos_t, 1e-12);
    const Rgb t = beer_transmittance(sigma, distance);
    EXPECT_NEAR(t.r, std::exp(-0.5 * 2 / cos_t), 1e-12);
    EXPECT_NEAR(t.g, std::exp(-1.0 * 2 / cos_t), 1e-12);
    EXPECT_NEAR(t.b, std::exp(-2.0 * 2 / cos_t), 1e-12);
    // Halving: ln 2 / σ of travel halves the light; transmittances multiply along a path.
    EXPECT_NEAR(beer_transmittance(Rgb(1.0), std::log(2.0)).r, 0.5, 1e-15);
    EXPECT_NEAR(beer_transmittance(sigma, 1.0).b * beer_transmittance(sigma, 2.0).b,
                beer_transmittance(sigma, 3.0).b, 1e-15);
    EXPECT_EQ(Dielectric(1.5, Rgb()).absorption(), Rgb());  // clear glass absorbs nothing
}

}  // namespace
}  // namespace glint
