#include <gtest/gtest.h>

#include "geometry/shape_testing.hpp"
#include "glint/core/polynomial.hpp"
#include "glint/geometry/torus.hpp"

namespace glint {
namespace {

using testing::check_area_samples;
using testing::check_random_hits;
using testing::check_scale_independence;
using testing::scene_error;

TEST(Polynomial, FindsEveryRealRootInTheInterval) {
    // (x − 1)(x − 2)(x − 3)(x − 4) = x⁴ − 10x³ + 35x² − 50x + 24
    const double c[5] = {24, -50, 35, -10, 1};
    double roots[4];
    ASSERT_EQ(polynomial_roots(c, 4, -10, 10, roots), 4);
    for (int i = 0; i < 4; ++i) {
        EXPECT_NEAR(roots[i], i + 1, 1e-14);
    }
    ASSERT_EQ(polynomial_roots(c, 4, 1.5, 3.5, roots), 2);
    EXPECT_NEAR(roots[0], 2, 1e-14);
    EXPECT_NEAR(roots[1], 3, 1e-14);
    // x⁴ + 1 has no real root; (x² − 2)² touches zero without crossing: not reported.
    const double none[5] = {1, 0, 0, 0, 1};
    EXPECT_EQ(polynomial_roots(none, 4, -10, 10, roots), 0);
    // Quadratics in closed form: (x − 3)(x + 0.5), and (x − 2)², whose double root is reported once.
    const double quadratic[3] = {-1.5, -2.5, 1};
    ASSERT_EQ(polynomial_roots(quadratic, 2, -10, 10, roots), 2);
    EXPECT_NEAR(roots[0], -0.5, 1e-15);
    EXPECT_NEAR(roots[1], 3, 1e-15);
    const double square[3] = {4, -4, 1};
    ASSERT_EQ(polynomial_roots(square, 2, -10, 10, roots), 1);
    EXPECT_EQ(roots[0], 2);
    // Two roots 1e-6 apart, where closed-form quartic solvers lose digits: (x−1)(x−1−1e-6)(x+2)(x−5).
    const double e = 1e-6;
    // Build it by multiplying out, to keep the test free of hand algebra.
    double p[5] = {1, 0, 0, 0, 0};  // the constant 1
    int degree = 0;
    for (const double r : {1.0, 1 + e, -2.0, 5.0}) {
        for (int i = degree + 1; i >= 0; --i) {
            p[i] = (i > 0 ? p[i - 1] : 0) - r * p[i];
        }
        ++degree;
    }
    ASSERT_EQ(polynomial_roots(p, 4, -10, 10, roots), 4);
    EXPECT_NEAR(roots[0], -2, 1e-12);
    EXPECT_NEAR(roots[1], 1, 1e-9);
    EXPECT_NEAR(roots[2], 1 + e, 1e-9);
    EXPECT_NEAR(roots[3], 5, 1e-12);
}

// A torus described the way the tests check it: centre, unit axis, radii.
struct TorusModel {
    Vec3 center, axis;
    double major, minor;

    Vec3 ring_point(const Vec3& p) const {
        const Vec3 q = p - center;
        const Vec3 in_plane = q - dot(q, axis) * axis;
        return center + major * normalize(in_plane);
    }
    // (|q|² + R² − r²)² − 4R²(x² + y²) = 0 is the same surface as this distance being zero.
    double distance(const Vec3& p) const { return std::abs(length(p - ring_point(p)) - minor); }
    double implicit(const Vec3& p) const {
        const Vec3 q = p - center;
        const double along = dot(q, axis);
        const double planar2 = dot(q, q) - along * along;
        return sqr(dot(q, q) + major * major - minor * minor) - 4 * major * major * planar2;
    }
    Vec3 normal(const Vec3& p) const { return normalize(p - ring_point(p)); }
};

TEST(Torus, HitsOutsideInsideAndThroughTheHole) {
    const Torus torus({0, 0, 0}, {0, 1, 0}, 2, 0.5);
    Hit hit;
    ASSERT_TRUE(torus.intersect({{-5, 0, 0}, {1, 0, 0}}, kInf, hit));
    EXPECT_NEAR(hit.t, 2.5, 1e-13);
    EXPECT_NEAR(testing::distance(hit.normal, {-1, 0, 0}), 0, 1e-13);
    ASSERT_TRUE(torus.intersect({{-5, 0, 0}, {1, 0, 0}}, 2.5 + 1e-9, hit));
    EXPECT_FALSE(torus.intersect({{-5, 0, 0}, {1, 0, 0}}, 2.5 - 1e-9, hit));  // t_max
    ASSERT_TRUE(torus.intersect({{2, 0, 0}, {1, 0, 0}}, kInf, hit));  // inside the tube: outward normal
    EXPECT_NEAR(hit.t, 0.5, 1e-13);
    EXPECT_NEAR(testing::distance(hit.normal, {1, 0, 0}), 0, 1e-13);
    ASSERT_TRUE(torus.intersect({{0, 0, 0}, {0, 0, 3}}, kInf, hit));  // from the hole
    EXPECT_NEAR(hit.t, 0.5, 1e-13);
    EXPECT_NEAR(testing::distance(hit.normal, {0, 0, -1}), 0, 1e-13);
    EXPECT_FALSE(torus.intersect({{0, 5, 0}, {0, -1, 0}}, kInf, hit));  // down the hole
    ASSERT_TRUE(torus.intersect({{2, 5, 0}, {0, -1, 0}}, kInf, hit));   // onto the top of the tube
    EXPECT_NEAR(hit.t, 4.5, 1e-13);
    EXPECT_NEAR(testing::distance(hit.normal, {0, 1, 0}), 0, 1e-13);
    EXPECT_FALSE(torus.intersect({{-5, 0, 0}, {-1, 0, 0}}, kInf, hit));    // behind
    EXPECT_FALSE(torus.intersect({{-5, 0.51, 0}, {1, 0, 0}}, kInf, hit));  // just over the tube
}

TEST(Torus, ManyRandomRaysHitPointsOnTheImplicitSurface) {
    const TorusModel m{{0.3, -0.2, 1}, normalize(Vec3{1, 2, -0.5}), 1.5, 0.4};
    const Torus torus(m.center, m.axis, m.major, m.minor);
    const int hits = check_random_hits(
        torus, [&](const Vec3& p) { return m.distance(p); }, [&](const Vec3& p) { return m.normal(p); },
        2000);
    EXPECT_GT(hits, 400);
    // The quartic itself: |implicit| ≤ |∇implicit| · (distance bound); |∇| ≤ 8R(R+r)r here.
    for (std::uint32_t i = 0; i < 500; ++i) {
        const Vec3 origin = m.center + 4 * testing::random_direction(31, i);
        const Ray ray{origin, testing::random_point_in(torus.bounds(), 32, i) - origin};
        Hit hit;
        if (torus.intersect(ray, kInf, hit)) {
            EXPECT_NEAR(m.implicit(hit.point), 0, 1e-10);
        }
    }
}

TEST(Torus, ThinTorusAndFarOrigins) {
    // A thin tube (r/R = 0.01) seen from far away still gives exact hits: the solver works in the
    // torus's own units and the origin is moved close before solving.
    const TorusModel m{{1000, 2000, -500}, {0, 0, 1}, 1, 0.01};
    const Torus torus(m.center, m.axis, m.major, m.minor);
    int hits = 0;
    for (std::uint32_t i = 0; i < 400; ++i) {
        const double phi = 2 * kPi * testing::uniform(41, i, 0);
        const Vec3 target =
            m.center + Vec3{std::cos(phi), std::sin(phi), 0.02 * testing::uniform(41, i, 1) - 0.01};
        const Vec3 origin = m.center + Vec3{300, -200, 150};
        Hit hit;
        if (torus.intersect({origin, target - origin}, kInf, hit)) {
            ++hits;
            EXPECT_NEAR(m.distance(hit.point), 0, 1e-12 * 3000);
        }
    }
    EXPECT_GT(hits, 100);
}

TEST(Torus, AreaSamplesAreUniform) {
    const TorusModel m{{0.3, -0.2, 1}, normalize(Vec3{1, 2, -0.5}), 1.5, 0.4};
    const Torus torus(m.center, m.axis, m.major, m.minor);
    EXPECT_NEAR(torus.area(), 4 * kPi * kPi * 1.5 * 0.4, 1e-12);
    const Vec3 mean = check_area_samples(
        torus, 100, [&](const Vec3& p) { return m.distance(p); }, 3.8);
    EXPECT_NEAR(testing::distance(mean, m.center), 0, 1e-6);
    // Uniform by area: per unit of φ the outer half of the tube (cos θ > 0) has area
    // ∫ r (R + r cos θ) dθ over |θ| < π/2 = r (π R + 2 r), against 2π r R for the whole tube.
    int outer = 0;
    for (int i = 0; i < 100; ++i) {
        for (int j = 0; j < 100; ++j) {
            const ShapeSample s = *torus.sample_area({(i + 0.5) / 100, (j + 0.5) / 100});
            outer += dot(s.normal, m.ring_point(s.point) - m.center) > 0;
        }
    }
    EXPECT_NEAR(outer / 1e4, (kPi * 1.5 + 2 * 0.4) / (2 * kPi * 1.5), 0.01);
}

TEST(Torus, SameHitsAtAnyScaleAndNoAcne) {
    check_scale_independence([](double s) {
        return std::make_unique<Torus>(Vec3{0.1, -0.5, 0.2} * s, Vec3{0.3, 1, 0.2}, 0.8 * s, 0.25 * s);
    });
}

TEST(Torus, MinorRadiusNotBelowMajorIsAPositionedError) {
    const std::string e = scene_error("objects:\n  - {type: torus, major_radius: 1, minor_radius: 1}\n");
    EXPECT_NE(e.find("test.yaml:2:50: error: torus minor_radius must be less than major_radius"),
              std::string::npos)
        << e;
}

}  // namespace
}  // namespace glint
