// Shape::sample_seen_from against the geometry alone: the directions it returns have the density its
// pdf says. For any weight g, E[g(ω) · visible / pdf] over its samples is ∫ g dω over the directions
// in which the reference point sees the shape, which ray casting estimates independently from
// uniformly distributed directions. pdf_seen_from() must agree with the pdf of each sample.
#include <gtest/gtest.h>

#include "geometry/shape_testing.hpp"
#include "glint/geometry/box.hpp"
#include "glint/geometry/disk.hpp"
#include "glint/geometry/instance.hpp"
#include "glint/geometry/rectangle.hpp"
#include "glint/geometry/sphere.hpp"
#include "glint/geometry/torus.hpp"

namespace glint {
namespace {

using testing::uniform;

// A Monte Carlo estimate and its standard error.
struct Estimate {
    double value = 0;
    double standard_error = 0;
};

// Accumulates independent values into their mean and its standard error.
struct MeanOf {
    double sum = 0, sum_squares = 0;
    int n = 0;
    void add(double v) {
        sum += v;
        sum_squares += v * v;
        ++n;
    }
    Estimate estimate() const {
        const double mean = sum / n;
        const double variance = std::max(0.0, sum_squares / n - mean * mean) * n / (n - 1);
        return {mean, std::sqrt(variance / n)};
    }
};

// Two weights: 1 (the solid angle) and one that varies over the sphere of directions, so that a density
// that is right on average but wrong in its shape is caught too.
constexpr int kWeights = 2;
double weight(int k, const Vec3& w) {
    return k == 0 ? 1.0 : std::exp(2 * dot(w, normalize(Vec3{0.3, -0.5, 0.8})));
}

// ∫ g dω over the directions in which `ref` sees the shape, by ray casting along directions that are
// uniformly distributed over the unit sphere (density 1 / 4π), stratified in (z, φ).
std::array<Estimate, kWeights> cast_integrals(const Shape& shape, const Vec3& ref, std::uint64_t seed) {
    constexpr int kSide = 700;
    std::array<MeanOf, kWeights> means;
    for (int i = 0; i < kSide; ++i) {
        for (int j = 0; j < kSide; ++j) {
            const auto index = static_cast<std::uint32_t>(i * kSide + j);
            const double z = 1 - 2 * (i + uniform(seed, index, 0)) / kSide;
            const double r = safe_sqrt(1 - z * z);
            const double phi = 2 * kPi * (j + uniform(seed, index, 1)) / kSide;
            const Vec3 w{r * std::cos(phi), r * std::sin(phi), z};
            const bool hits = shape.occluded(Ray{ref, w}, kInf);
            for (int k = 0; k < kWeights; ++k) {
                means[static_cast<size_t>(k)].add(hits ? 4 * kPi * weight(k, w) : 0.0);
            }
        }
    }
    // The standard error of independent directions: stratification only lowers it.
    return {means[0].estimate(), means[1].estimate()};
}

// The same integrals from the shape's own samples, counting only the samples that `ref` sees (the
// first point its ray along ω meets). Checks that pdf_seen_from() agrees with each visible sample and
// returns the fraction of samples that are visible.
struct SampledIntegrals {
    std::array<Estimate, kWeights> integrals;
    double visible_fraction = 0;
};

SampledIntegrals sampled_integrals(const Shape& shape, const Vec3& ref, std::uint64_t seed) {
    constexpr int kSamples = 200000;
    const double size = max_component(shape.bounds().extent());
    std::array<MeanOf, kWeights> means;
    int visible = 0;
    for (std::uint32_t i = 0; i < kSamples; ++i) {
        const std::optional<SeenSample> s =
            shape.sample_seen_from(ref, {uniform(seed, i, 0), uniform(seed, i, 1)});
        Hit hit;
        const bool seen = s && shape.intersect(Ray{ref, s->wi}, kInf, hit) &&
                          testing::distance(hit.point, s->point) < 1e-7 * size;
        if (seen) {
            ++visible;
            EXPECT_NEAR(length(s->wi), 1, 1e-12);
            EXPECT_NEAR(testing::distance(s->wi, normalize(s->point - ref)), 0, 1e-9);
            EXPECT_NEAR(testing::distance(s->normal, hit.normal), 0, 1e-6) << "sample " << i;
            // Area densities divide by |cos θ| at the point: seen edge-on, the last digits of the hit's
            // normal (~1e-10 off for a torus) become a relative error of the pdf of ~1e-10 / |cos θ|.
            const double cos_at_point = std::abs(dot(s->normal, s->wi));
            EXPECT_NEAR(shape.pdf_seen_from(ref, s->wi, hit), s->pdf_solid_angle,
                        (1e-7 + 1e-9 / cos_at_point) * s->pdf_solid_angle)
                << "sample " << i;
        }
        for (int k = 0; k < kWeights; ++k) {
            means[static_cast<size_t>(k)].add(seen ? weight(k, s->wi) / s->pdf_solid_angle : 0.0);
        }
    }
    return {{means[0].estimate(), means[1].estimate()}, static_cast<double>(visible) / kSamples};
}

// Both estimates of both integrals agree within 4 standard errors, and the errors are small enough
// (below 1% of the value) for the agreement to mean something. Returns the fraction of visible samples.
double check_seen_from(const Shape& shape, const Vec3& ref, const std::string& what) {
    SCOPED_TRACE(what);
    const std::array<Estimate, kWeights> cast = cast_integrals(shape, ref, 31);
    const SampledIntegrals sampled = sampled_integrals(shape, ref, 32);
    for (int k = 0; k < kWeights; ++k) {
        const Estimate& a = cast[static_cast<size_t>(k)];
        const Estimate& b = sampled.integrals[static_cast<size_t>(k)];
        const double error = std::hypot(a.standard_error, b.standard_error);
        EXPECT_GT(a.value, 0);
        EXPECT_LT(error, 0.01 * a.value) << "weight " << k;
        EXPECT_NEAR(b.value, a.value, 4 * error) << "weight " << k;
    }
    return sampled.visible_fraction;
}

// The exact solid angle of a sphere of radius R whose centre is d away: 2π (1 − cos θ), sin θ = R/d.
double sphere_solid_angle(double radius, double d) {
    return 2 * kPi * (1 - std::sqrt(1 - sqr(radius / d)));
}

TEST(SeenFromSampling, SphereFromOutsideSamplesOnlyItsVisibleCone) {
    const Sphere sphere({0.3, 2, -0.4}, 0.9);
    const Vec3 ref{0.1, 0, 0.2};
    EXPECT_EQ(check_seen_from(sphere, ref, "sphere"), 1.0);  // no sample on the far side
    const std::optional<SeenSample> s = sphere.sample_seen_from(ref, {0.4, 0.9});
    ASSERT_TRUE(s);
    EXPECT_NEAR(1 / s->pdf_solid_angle, sphere_solid_angle(0.9, length(sphere.center() - ref)), 1e-12);
}

// The density a cone sample carries is the very double pdf_seen_from gives for its direction, near the
// sphere and far from it, so that the MIS weights of a light sample and of a BSDF sample that meets the
// light are computed from the same value.
TEST(SeenFromSampling, ASphereConeSampleCarriesTheDensityPdfSeenFromGives) {
    const Sphere sphere({0.3, 2, -0.4}, 0.9);
    for (const Vec3& ref :
         {Vec3{0.1, 0, 0.2}, Vec3{0.3, 0.95, -0.4}, Vec3{40, -70, 25}, Vec3{1e4, 3e3, -2e4}}) {
        for (const Point2 u : {Point2{0.4, 0.9}, Point2{0.01, 0.3}, Point2{0.999, 0.6}}) {
            const std::optional<SeenSample> s = sphere.sample_seen_from(ref, u);
            ASSERT_TRUE(s);
            EXPECT_EQ(s->pdf_solid_angle, sphere.pdf_seen_from(ref, s->wi, s->point, s->normal));
            // The solid angle 2π (1 − cos θ) as 2π sin² θ / (1 + cos θ), which keeps its digits in
            // the far reference points' narrow cones (sphere_solid_angle loses half of them there).
            const double sin2 = sqr(0.9) / length_squared(sphere.center() - ref);
            EXPECT_NEAR(s->pdf_solid_angle * (2 * kPi * sin2 / (1 + std::sqrt(1 - sin2))), 1.0, 1e-14);
        }
    }
}

TEST(SeenFromSampling, SphereFromInsideSamplesByArea) {
    const Sphere sphere({0.3, 2, -0.4}, 0.9);
    check_seen_from(sphere, {0.5, 1.7, 0}, "inside the sphere");
}

TEST(SeenFromSampling, TransformedSpheresSampleTheirCone) {
    // Two ways to place a sphere of radius 0.9 at c: moved there, or grown from radius 2 and turned.
    const Vec3 ref{0.1, 0, 0.2}, c{0.3, 2, -0.4};
    struct Placed {
        double radius;
        Transform transform;
        const char* what;
    };
    for (const Placed& placed : {Placed{0.9, Transform::translate(c), "translated"},
                                 Placed{2,
                                        Transform::scale(Vec3{0.45, 0.45, 0.45})
                                            ->then(Transform::rotate({1, 2, -1}, 50))
                                            .then(Transform::translate(c)),
                                        "rotated and scaled"}}) {
        const Instance sphere(std::make_unique<Sphere>(Vec3{}, placed.radius), placed.transform);
        EXPECT_EQ(check_seen_from(sphere, ref, placed.what), 1.0);
        const std::optional<SeenSample> s = sphere.sample_seen_from(ref, {0.4, 0.9});
        ASSERT_TRUE(s);
        EXPECT_NEAR(1 / s->pdf_solid_angle, sphere_solid_angle(0.9, length(c - ref)), 1e-12) << placed.what;
    }
}

TEST(SeenFromSampling, EllipsoidSamplesTheConeOfItsSphere) {
    // A non-uniform scale and a shear: the density changes over the directions, by the Jacobian.
    const Transform stretch =
        Transform::scale(Vec3{1.6, 0.5, 0.9})
            ->then(*Transform::from_matrix({{{1, 0.4, 0, 0}, {0, 1, 0, 0}, {0, 0.3, 1, 0}}}))
            .then(Transform::rotate({0, 1, 1}, 35))
            .then(Transform::translate({0.3, 2, -0.4}));
    const Instance ellipsoid(std::make_unique<Sphere>(Vec3{}, 1), stretch);
    EXPECT_EQ(check_seen_from(ellipsoid, {0.1, -0.5, 0.2}, "outside the ellipsoid"), 1.0);
    check_seen_from(ellipsoid, {0.4, 2.1, -0.3}, "inside the ellipsoid");
    // Close to it, where the density varies most over the directions.
    EXPECT_EQ(check_seen_from(ellipsoid, stretch.point({0, 0, 1.3}), "just outside the ellipsoid"), 1.0);
}

TEST(SeenFromSampling, OtherShapesSampleByArea) {
    const Vec3 ref{0.1, 0, 0.2};
    check_seen_from(Rectangle({-1, 1, -0.5}, {2.5, 0.3, 0}, {0, 0.2, 1.5}), ref, "rectangle");
    check_seen_from(Disk({0.5, 1.2, 0.3}, normalize(Vec3{0.3, -1, 0.2}), 0.9), ref, "disk");
    // Closed and non-convex: a share of the samples lies behind the shape's own near side.
    EXPECT_LT(check_seen_from(Torus({0, 1.5, 0}, normalize(Vec3{0.2, 1, 0.1}), 1, 0.3), ref, "torus"), 0.8);
    // By area in world space (a similarity) and in the box's own space (a stretch and a shear).
    const Transform similar = Transform::scale(Vec3{1.5, 1.5, 1.5})
                                  ->then(Transform::rotate({1, 1, 0}, 30))
                                  .then(Transform::translate({0, 2, 0}));
    check_seen_from(Instance(std::make_unique<Box>(Vec3{-0.5, -0.5, -0.5}, Vec3{0.5, 0.5, 0.5}), similar),
                    ref, "rotated box");
    const Transform sheared =
        Transform::scale(Vec3{2, 0.4, 1})
            ->then(*Transform::from_matrix({{{1, 0, 0.5, 0}, {0.2, 1, 0, 0}, {0, 0, 1, 0}}}))
            .then(Transform::translate({0, 2, 0}));
    const Instance box(std::make_unique<Box>(Vec3{-0.5, -0.5, -0.5}, Vec3{0.5, 0.5, 0.5}), sheared);
    check_seen_from(box, ref, "sheared box");
    check_seen_from(box, sheared.point({0.1, 0.2, -0.3}), "inside the sheared box");
}

// seen_from converts by d³ / |n · (point − ref)| with 1/d² (shape.hpp): a point so near or so far that
// d² is subnormal or infinite gives no sample, never a direction or a density that is not finite.
TEST(SeenFromSampling, APointAtADistanceWhoseSquareIsNotNormalGivesNoSample) {
    const Vec3 normal{0, 0, -1};
    const Vec3 ref{0, 0, 0};                          // where tiny offsets are not rounded away
    for (const double distance : {1e-170, 1e-160}) {  // d² underflowing to 0, and subnormal
        EXPECT_FALSE(seen_from(ref, {ref + Vec3{0, 0, distance}, normal, 1.0})) << distance;
    }
    EXPECT_FALSE(seen_from(ref, {ref + Vec3{0, 0, 1e160}, normal, 1.0}));  // d² overflows
    // The same sample nearer to and farther from the edges of the range is kept, finite and exact
    // enough: the direction a unit vector, the density d² / |cos θ|.
    for (const double distance : {1e-150, 1e-3, 1.0, 1e3, 1e150}) {
        const std::optional<SeenSample> seen =
            seen_from(ref, {ref + Vec3{0, distance * 0.6, distance * 0.8}, normal, 2.0});
        ASSERT_TRUE(seen) << distance;
        EXPECT_NEAR(length(seen->wi), 1.0, 1e-15) << distance;
        EXPECT_NEAR(seen->pdf_solid_angle / (2.0 * distance * distance / 0.8), 1.0, 1e-14) << distance;
    }
}

}  // namespace
}  // namespace glint
