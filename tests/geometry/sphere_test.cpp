#include "glint/geometry/sphere.hpp"

#include <gtest/gtest.h>

#include "glint/core/hash.hpp"

namespace glint {
namespace {

TEST(Sphere, HitFromOutsideTakesTheNearRoot) {
    const Sphere s({0, 0, 0}, 1);
    Hit hit;
    ASSERT_TRUE(s.intersect({{0, 0, 5}, {0, 0, -1}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 4.0);
    EXPECT_NEAR(hit.point.z, 1.0, 1e-15);
    EXPECT_EQ(hit.normal, Vec3(0, 0, 1));
}

TEST(Sphere, UvIsLongitudeAboutYAndColatitudeFromY) {
    // u = φ/2π with φ from +x towards +z, v = θ/π from +y: known at the axes and at one oblique point.
    const Sphere s({1, 2, 3}, 2);
    const auto uv_from = [&](const Vec3& direction) {
        Hit hit;
        EXPECT_TRUE(s.intersect({Vec3{1, 2, 3} + 10 * direction, -direction}, kInf, hit));
        return surface_uv(hit);
    };
    EXPECT_NEAR(uv_from({1, 0, 0}).x, 0.0, 1e-15);
    EXPECT_NEAR(uv_from({1, 0, 0}).y, 0.5, 1e-15);
    EXPECT_NEAR(uv_from({0, 0, 1}).x, 0.25, 1e-15);
    EXPECT_NEAR(uv_from({-1, 0, 0}).x, 0.5, 1e-15);
    EXPECT_NEAR(uv_from({0, 0, -1}).x, 0.75, 1e-15);
    EXPECT_NEAR(uv_from({0, 1, 0}).y, 0.0, 1e-7);  // acos near 1 amplifies the normal's rounding
    EXPECT_NEAR(uv_from({0, -1, 0}).y, 1.0, 1e-7);
    // 45° below +y, halfway from +z to −x: φ = 135°, θ = 135°.
    const Point2 oblique = uv_from(normalize(Vec3{-0.5, -std::sqrt(0.5), 0.5}));
    EXPECT_NEAR(oblique.x, 0.375, 1e-14);
    EXPECT_NEAR(oblique.y, 0.75, 1e-14);
}

TEST(Sphere, UvIsComputedOnDemandAndOverwrittenByALaterHit) {
    // The sphere leaves the marker; a hit record then reused by a nearer shape gets that shape's uv.
    const Sphere s({0, 0, 0}, 1);
    Hit hit;
    ASSERT_TRUE(s.intersect({{0, 0, 5}, {0, 0, -1}}, kInf, hit));
    EXPECT_TRUE(uv_deferred(hit));
    hit.uv = {0.1, 0.2};
    EXPECT_FALSE(uv_deferred(hit));
    EXPECT_EQ(surface_uv(hit).x, 0.1);
}

TEST(Sphere, TIsInUnitsOfTheDirection) {
    const Sphere s({0, 0, 0}, 1);
    Hit hit;
    ASSERT_TRUE(s.intersect({{0, 0, 5}, {0, 0, -2}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 2.0);
}

TEST(Sphere, HitFromInsideTakesTheFarRootWithOutwardNormal) {
    const Sphere s({1, 2, 3}, 2);
    Hit hit;
    ASSERT_TRUE(s.intersect({{1, 2, 3}, {1, 0, 0}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 2.0);
    EXPECT_NEAR(hit.normal.x, 1.0, 1e-15);  // outward even though the ray is inside
}

TEST(Sphere, SphereBehindTheRayIsMissed) {
    const Sphere s({0, 0, -5}, 1);
    Hit hit;
    EXPECT_FALSE(s.intersect({{0, 0, 0}, {0, 0, 1}}, kInf, hit));
    EXPECT_FALSE(s.occluded({{0, 0, 0}, {0, 0, 1}}, kInf));
}

TEST(Sphere, RaysGoingAwayFromTheCentreHitOnlyFromInside) {
    // From outside or on the surface, a ray going away from the centre misses without the roots being
    // solved (sphere_roots' early answer); from inside, it meets the far side.
    const Sphere s({1, 2, 3}, 2);
    Hit hit;
    const Vec3 away = normalize(Vec3{1, 0.5, -0.25});
    EXPECT_FALSE(s.intersect({Vec3{1, 2, 3} + 2.5 * away, away}, kInf, hit));  // outside
    EXPECT_FALSE(s.occluded({Vec3{1, 2, 3} + 2.5 * away, away}, kInf));
    EXPECT_FALSE(s.intersect({{3, 2, 3}, {1, 0, 0}}, kInf, hit));  // on the surface (c = 0 exactly)
    EXPECT_FALSE(s.intersect({{3, 2, 3}, {1, 1, 0}}, kInf, hit));  // on it, leaving obliquely
    ASSERT_TRUE(s.intersect({{3, 2, 3}, {-1, 0, 0}}, kInf, hit));  // on it, going in: the far side
    EXPECT_DOUBLE_EQ(hit.t, 4.0);
    // Inside, off the centre, going away from it (h > 0, c < 0): the far side, ahead.
    ASSERT_TRUE(s.intersect({{2, 2, 3}, {1, 0, 0}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 1.0);
    EXPECT_TRUE(s.occluded({{2, 2, 3}, {1, 0, 0}}, 1.5));
    ASSERT_TRUE(s.intersect(Ray{Vec3{1, 2, 3} + 1.5 * away, away}, kInf, hit));
    EXPECT_NEAR(hit.t, 0.5, 1e-15);
}

TEST(Sphere, TangentRayTouchesOnceAndAMissMisses) {
    const Sphere s({0, 0, 0}, 1);
    Hit hit;
    ASSERT_TRUE(s.intersect({{1, 0, 5}, {0, 0, -1}}, kInf, hit));  // grazes at (1, 0, 0)
    EXPECT_NEAR(hit.t, 5.0, 1e-7);
    EXPECT_NEAR(hit.point.x, 1.0, 1e-12);
    EXPECT_FALSE(s.intersect({{1.0000001, 0, 5}, {0, 0, -1}}, kInf, hit));
}

TEST(Sphere, TMaxIsRespected) {
    const Sphere s({0, 0, 0}, 1);
    Hit hit;
    EXPECT_FALSE(s.intersect({{0, 0, 5}, {0, 0, -1}}, 4.0, hit));
    EXPECT_TRUE(s.intersect({{0, 0, 5}, {0, 0, -1}}, 4.0001, hit));
    EXPECT_FALSE(s.occluded({{0, 0, 5}, {0, 0, -1}}, 3.9));
}

TEST(Sphere, SmallFarSphereKeepsPrecision) {
    // The naive discriminant b² − 4ac cancels catastrophically here (b² ≈ 4ac ≈ 1e24 while the
    // difference is ~1e-2); the robust form still finds the hit at the right distance.
    const double r = 1e-3;
    const Sphere s({0, 0, -1e6}, r);
    Hit hit;
    ASSERT_TRUE(s.intersect({{0, 0, 0}, {0, 0, -1}}, kInf, hit));
    EXPECT_NEAR(hit.t, 1e6 - r, 1e-9 * 1e6);
    ASSERT_TRUE(s.intersect({{0.5 * r, 0, 0}, {0, 0, -1}}, kInf, hit));
    EXPECT_NEAR(hit.point.z, -1e6 + r * std::sqrt(0.75), 1e-9);
    // A ray that passes just outside must miss.
    EXPECT_FALSE(s.intersect({{1.001 * r, 0, 0}, {0, 0, -1}}, kInf, hit));
}

TEST(Sphere, RandomHitsLieOnTheSphereAndLeavingRaysDoNotRehit) {
    for (double scale : {1e-3, 1.0, 1e5}) {
        const Vec3 center = Vec3{0.3, -0.7, 2.0} * scale;
        const Sphere s(center, scale);
        for (std::uint32_t i = 0; i < 2000; ++i) {
            const SampleKey key{11, i, 0, 0};
            const Vec3 origin = center + Vec3{key.uniform(0) - 0.5, key.uniform(1) - 0.5, 5} * scale;
            const Vec3 target =
                center + Vec3{key.uniform(2) - 0.5, key.uniform(3) - 0.5, key.uniform(4) - 0.5} * scale;
            const Ray ray{origin, target - origin};
            Hit hit;
            ASSERT_TRUE(s.intersect(ray, kInf, hit));
            EXPECT_NEAR(length(hit.point - center), scale, 1e-12 * scale);
            // Reflected and transmitted rays leaving the hit point never hit the same surface at ~0.
            const Vec3 out = reflect(normalize(ray.direction), hit.normal);
            Hit again;
            EXPECT_FALSE(s.intersect(spawn_ray(hit, out), kInf, again)) << "scale " << scale << " ray " << i;
            ASSERT_TRUE(s.intersect(spawn_ray(hit, ray.direction), kInf, again));
            EXPECT_GT(again.t * length(ray.direction), 1e-6 * scale);  // the far side, not the same point
        }
    }
}

TEST(Sphere, FillHitProjectsAnInexactTOntoTheSphere) {
    // fill_hit's normal comes from the radius vector over the radius, which is unit only as far as t is
    // exact: given t's off by 1e-9 (inside normalize_near_unit's Newton step) and by 1e-3 (outside it),
    // in rays head-on and grazing, its normal is unit and its point on the sphere all the same.
    for (double scale : {1e-3, 1.0, 1e3, 1e5}) {
        const Vec3 center = Vec3{0.3, -0.7, 2.0} * scale;
        const Sphere s(center, scale);
        for (std::uint32_t i = 0; i < 2000; ++i) {
            const SampleKey key{12, i, 0, 0};
            const double miss_by = std::ldexp(key.uniform(0), -static_cast<int>(i % 40));  // 1 to 2^-40
            const double angle = 2 * kPi * key.uniform(1);
            const Vec3 side{std::cos(angle), std::sin(angle), 0};
            const Vec3 origin = center + (side * (1 - miss_by) + Vec3{0, 0, 3}) * scale;
            const Ray ray{origin, Vec3{key.uniform(2) * 1e-3, 0, -1}};
            Hit hit;
            if (!s.intersect(ray, kInf, hit)) {
                continue;
            }
            for (double error : {0.0, 1e-9, -1e-9, 1e-3}) {
                Hit inexact;
                s.fill_hit(ray, hit.t * (1 + error), inexact);
                EXPECT_NEAR(length(inexact.normal), 1.0, 1e-15) << scale << " " << i << " " << error;
                EXPECT_NEAR(length(inexact.point - center), scale, 1e-15 * scale) << scale << " " << i;
                EXPECT_EQ(inexact.normal, inexact.shading_normal);
            }
        }
    }
}

TEST(Sphere, AreaSamplesLieOnTheSurfaceWithUniformDensity) {
    const Sphere s({1, 2, 3}, 2);
    Vec3 mean;
    constexpr int kN = 20000;
    for (std::uint32_t i = 0; i < kN; ++i) {
        const SampleKey key{5, i, 0, 0};
        const auto sample = s.sample_area({key.uniform(0), key.uniform(1)});
        ASSERT_TRUE(sample);
        EXPECT_NEAR(length(sample->point - Vec3(1, 2, 3)), 2.0, 1e-12);
        EXPECT_DOUBLE_EQ(sample->pdf_area, 1 / (16 * kPi));
        mean += sample->point / kN;
    }
    // The centroid of a uniform sphere is its centre; each coordinate has σ = r/√3 per sample.
    EXPECT_NEAR(length(mean - Vec3(1, 2, 3)), 0.0, 5 * 2 / std::sqrt(3.0 * kN) * std::sqrt(3.0));
}

}  // namespace
}  // namespace glint
