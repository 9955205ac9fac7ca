// χ² tests of each light's sampling against its own pdf, and the agreement of sample() with pdf().
#include <gtest/gtest.h>

#include "glint/core/frame.hpp"
#include "glint/core/hash.hpp"
#include "glint/geometry/disk.hpp"
#include "glint/geometry/instance.hpp"
#include "glint/geometry/rectangle.hpp"
#include "glint/geometry/sphere.hpp"
#include "glint/light/area.hpp"
#include "glint/light/directional.hpp"
#include "glint/light/environment.hpp"
#include "glint/light/spot.hpp"
#include "glint/sampling/distribution.hpp"
#include "integrator/radiance_util.hpp"

namespace glint {
namespace {

// Independent uniform points: a hash of the index, so the test is deterministic.
Point2 uniform_point(std::uint64_t i) {
    const std::uint64_t h = hash_values(0x5eed, i);
    return {static_cast<double>(h >> 11) * 0x1p-53, static_cast<double>(hash_values(h, 7) >> 11) * 0x1p-53};
}

Hit surface_at(const Vec3& point, const Vec3& normal) {
    Hit h;
    h.point = point;
    h.normal = normal;
    h.shading_normal = normal;
    return h;
}

// Bins sampled directions by (cos θ, φ) about `axis`, cos θ in [cos_min, 1], against the expected
// counts from integrating pdf(ω) over each bin (midpoint rule on sub-cells). Directions outside the
// range fall into one more cell whose expectation is what the range leaves.
struct DirectionHistogram {
    Frame frame;
    double cos_min;
    int rows = 16, columns = 32;
    int sub = 8;  // sub-cells per cell side for the midpoint rule

    int cell(const Vec3& w) const {
        const Vec3 local = frame.to_local(w);
        if (local.z < cos_min) {
            return rows * columns;
        }
        const int row = std::min(rows - 1, static_cast<int>((local.z - cos_min) / (1 - cos_min) * rows));
        double phi = std::atan2(local.y, local.x);
        phi = phi < 0 ? phi + 2 * kPi : phi;
        const int column = std::min(columns - 1, static_cast<int>(phi / (2 * kPi) * columns));
        return row * columns + column;
    }

    template <typename Pdf>
    std::vector<double> expected(Pdf&& pdf, double n) const {
        const int kSub = sub;
        std::vector<double> e(static_cast<size_t>(rows * columns + 1), 0.0);
        const double d_cos = (1 - cos_min) / (rows * kSub);
        const double d_phi = 2 * kPi / (columns * kSub);
        double total = 0;
        for (int r = 0; r < rows * kSub; ++r) {
            for (int c = 0; c < columns * kSub; ++c) {
                const double z = cos_min + (r + 0.5) * d_cos;
                const double phi = (c + 0.5) * d_phi;
                const double s = safe_sqrt(1 - z * z);
                const Vec3 w = frame.to_world({s * std::cos(phi), s * std::sin(phi), z});
                const double p = pdf(w) * d_cos * d_phi * n;
                e[static_cast<size_t>((r / kSub) * columns + c / kSub)] += p;
                total += p;
            }
        }
        e.back() = std::max(0.0, n - total);
        return e;
    }
};

constexpr int kSamples = 100000;
constexpr double kSignificance = 1e-3;

// The hit of a ray from `at` along w on `shape`, for pdf(…, on_light).
std::optional<Hit> hit_on(const Shape& shape, const Hit& at, const Vec3& w) {
    Hit h;
    if (!shape.intersect(Ray{at.point, w}, kInf, h)) {
        return std::nullopt;
    }
    return h;
}

// A shape with edges has a density that jumps at them: `coarse` uses fewer, finer-integrated cells there.
void check_area_light(const Shape& sphere, const Hit& at, double cos_min, const Vec3& axis,
                      bool coarse = false) {
    const AreaEmitter emitter(Rgb(2.0), true);
    const AreaLight light(sphere, emitter, 1);
    DirectionHistogram histogram{Frame::from_normal(axis), cos_min};
    if (coarse) {
        histogram.rows = 8;
        histogram.columns = 16;
        histogram.sub = 64;
    }
    std::vector<double> observed(static_cast<size_t>(histogram.rows * histogram.columns + 1), 0.0);
    int missing = 0;
    for (int i = 0; i < kSamples; ++i) {
        const std::optional<LightSample> s = light.sample(at, uniform_point(static_cast<std::uint64_t>(i)));
        if (!s) {
            ++missing;
            continue;
        }
        observed[static_cast<size_t>(histogram.cell(s->wi))] += 1;
        // sample() and pdf() agree, and the sample carries the emitted radiance.
        const std::optional<Hit> h = hit_on(sphere, at, s->wi);
        if (i % 97 == 0 && h) {
            EXPECT_NEAR(light.pdf(at, s->wi, &*h), s->pdf, 1e-6 * s->pdf);
            EXPECT_LT(length(h->point - s->position), 1e-6);
        }
        EXPECT_EQ(s->radiance, Rgb(2.0));
        EXPECT_FALSE(s->delta);
    }
    EXPECT_EQ(missing, 0);
    const auto expected = histogram.expected(
        [&](const Vec3& w) {
            const std::optional<Hit> h = hit_on(sphere, at, w);
            return h ? light.pdf(at, w, &*h) : 0.0;
        },
        kSamples - missing);
    EXPECT_GT(test::chi2_p_value(observed, expected), kSignificance);
}

TEST(LightSampling, SphereLightFromOutsideSamplesItsConeUniformly) {
    const Sphere sphere({0, 3, 0}, 1);
    const Hit at = surface_at({0.5, 0, 0.2}, {0, 1, 0});
    const Vec3 to_center = sphere.center() - at.point;
    const double cos_max = std::sqrt(1 - 1 / length_squared(to_center));
    // The range starts exactly at the cone's edge, where the pdf drops to zero.
    check_area_light(sphere, at, cos_max, normalize(to_center));
    // The cone's solid angle is 1/pdf.
    const AreaEmitter emitter(Rgb(1.0), false);
    const AreaLight light(sphere, emitter, 1);
    EXPECT_NEAR(1 / light.sample(at, {0.3, 0.6})->pdf, 2 * kPi * (1 - cos_max), 1e-12);
}

TEST(LightSampling, TransformedSphereLightsSampleTheirCone) {
    // A moved sphere: uniform over its cone, as the sphere placed by its centre.
    const Hit at = surface_at({0.5, 0, 0.2}, {0, 1, 0});
    const Vec3 center{0, 3, 0};
    const Instance moved(std::make_unique<Sphere>(Vec3{}, 1), Transform::translate(center));
    const Vec3 to_center = center - at.point;
    check_area_light(moved, at, std::sqrt(1 - 1 / length_squared(to_center)), normalize(to_center));
    // An ellipsoid (semi-axes 1.6, 0.5, 0.9, turned): the cone of its unit sphere, its density changed by
    // the transform's Jacobian. The histogram covers the cone of a sphere of radius 1.6 around it, with
    // the coarse cells for a density that drops to zero inside them, at the ellipsoid's outline.
    const Instance ellipsoid(std::make_unique<Sphere>(Vec3{}, 1), Transform::scale({1.6, 0.5, 0.9})
                                                                      ->then(Transform::rotate({1, 0, 1}, 40))
                                                                      .then(Transform::translate(center)));
    check_area_light(ellipsoid, at, std::sqrt(1 - sqr(1.6) / length_squared(to_center)), normalize(to_center),
                     true);
}

TEST(LightSampling, SphereLightFromInsideSamplesByArea) {
    const Sphere sphere({0, 0, 0}, 2);
    const Hit at = surface_at({0.3, -0.8, 0.5}, {0, 1, 0});
    check_area_light(sphere, at, -1, {0, 1, 0});
}

TEST(LightSampling, RectangleAndDiskLightsSampleByArea) {
    // Seen obliquely and close, so the solid-angle density varies strongly over the shape.
    const Hit at = surface_at({0.2, 0, 0.1}, {0, 1, 0});
    check_area_light(Rectangle({-1, 1, -0.5}, {2.5, 0.3, 0}, {0, 0.2, 1.5}), at, 0, {0, 1, 0}, true);
    check_area_light(Disk({0.5, 1.2, 0.3}, normalize(Vec3{0.3, -1, 0.2}), 0.9), at, 0, {0, 1, 0}, true);
    // Σ 1/pdf over samples estimates the solid angle; for a small rectangle seen head-on it is ≈ A / d².
    const Rectangle small({-0.01, 10, -0.01}, {0.02, 0, 0}, {0, 0, 0.02});
    const AreaEmitter emitter(Rgb(1.0), true);
    const AreaLight light(small, emitter, 1);
    const Hit origin = surface_at({0, 0, 0}, {0, 1, 0});
    EXPECT_NEAR(1 / light.sample(origin, {0.5, 0.5})->pdf, 0.0004 / 100, 1e-9);
}

TEST(LightSampling, FarTinySphereKeepsItsPrecision) {
    // sin² θ_max = 1e-14: 1 − cos θ_max computed as 1 − √(1 − s²) would be mostly rounding error.
    const Sphere sphere({0, 1e7, 0}, 1);
    const AreaEmitter emitter(Rgb(1.0), false);
    const AreaLight light(sphere, emitter, 1);
    const Hit at = surface_at({0, 0, 0}, {0, 1, 0});
    const auto s = light.sample(at, {0.5, 0.5});
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->pdf * 2 * kPi * 0.5e-14, 1.0, 1e-9);
    EXPECT_NEAR(length(s->position - sphere.center()), 1.0, 1e-6);
}

TEST(LightSampling, EnvironmentImageIsImportanceSampled) {
    // A 6×4 map with one bright pixel, a dim one and a black one: the samples follow luminance · sin θ.
    Image image(6, 4);
    for (float& v : image.rgb) {
        v = 0.2f;
    }
    image.pixel(4, 1)[0] = 9;
    image.pixel(4, 1)[1] = 5;
    image.pixel(1, 2)[2] = 0.01f;
    for (int c = 0; c < 3; ++c) {
        image.pixel(0, 3)[c] = 0;
    }
    const EnvironmentLight light(image, 0);
    const Hit at = surface_at({1, 2, 3}, {0, 1, 0});
    // Histogram over the map's (u, v), 4 × 4 cells per pixel; the expected count of a cell is
    // N ∫ pdf(ω) dω = N ∫ pdf(ω(u, v)) 2π² sin θ du dv (midpoint rule on 8 × 8 sub-cells).
    constexpr int kColumns = 24, kRows = 16, kSub = 8;
    std::vector<double> observed(kColumns * kRows, 0.0);
    for (int i = 0; i < kSamples; ++i) {
        const auto s = light.sample(at, uniform_point(static_cast<std::uint64_t>(i)));
        ASSERT_TRUE(s);
        const Point2 uv = EnvironmentLight::direction_to_uv(s->wi);
        observed[static_cast<size_t>(std::min(kRows - 1, static_cast<int>(uv.y * kRows)) * kColumns +
                                     std::min(kColumns - 1, static_cast<int>(uv.x * kColumns)))] += 1;
        EXPECT_TRUE(s->infinite);
        if (i % 53 == 0) {
            EXPECT_NEAR(light.pdf(at, s->wi, nullptr), s->pdf, 1e-9 * s->pdf);
            EXPECT_EQ(light.escaped(s->wi), s->radiance);
        }
    }
    std::vector<double> expected(kColumns * kRows, 0.0);
    double total = 0;
    for (int r = 0; r < kRows * kSub; ++r) {
        for (int c = 0; c < kColumns * kSub; ++c) {
            const Point2 uv{(c + 0.5) / (kColumns * kSub), (r + 0.5) / (kRows * kSub)};
            const double jacobian = 2 * kPi * kPi * std::sin(kPi * uv.y) / (kColumns * kSub * kRows * kSub);
            const double e =
                light.pdf(at, EnvironmentLight::uv_to_direction(uv), nullptr) * jacobian * kSamples;
            expected[static_cast<size_t>((r / kSub) * kColumns + c / kSub)] += e;
            total += e;
        }
    }
    EXPECT_NEAR(total, kSamples, 1e-3 * kSamples);  // the pdf integrates to one over the sphere
    EXPECT_GT(test::chi2_p_value(observed, expected), kSignificance);
    // The black pixel's directions are never sampled and have density zero.
    EXPECT_EQ(light.pdf(at, EnvironmentLight::uv_to_direction({0.5 / 6, 3.5 / 4}), nullptr), 0);

    // A rotation about +y turns the map: the rotated light sees in R·d what the unrotated sees in d.
    const EnvironmentLight rotated(image, 30);
    const double c = std::cos(radians(30)), s = std::sin(radians(30));
    for (int i = 0; i < 50; ++i) {
        const Vec3 d = EnvironmentLight::uv_to_direction(uniform_point(static_cast<std::uint64_t>(i) + 999));
        const Vec3 turned{c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
        EXPECT_EQ(rotated.escaped(turned), light.escaped(d));
        EXPECT_NEAR(rotated.pdf(at, turned, nullptr), light.pdf(at, d, nullptr), 1e-9);
    }
}

TEST(LightSampling, EnvironmentMapConventionRoundTrips) {
    for (const Vec3& d : {Vec3{0, 0, -1}, Vec3{0.6, 0.0, 0.8}, normalize(Vec3{-1, 2, 0.5})}) {
        const Vec3 back = EnvironmentLight::uv_to_direction(EnvironmentLight::direction_to_uv(d));
        EXPECT_LT(length(back - d), 1e-12) << d;
    }
    // The image centre is −z, the top row +y.
    const Point2 front = EnvironmentLight::direction_to_uv({0, 0, -1});
    EXPECT_NEAR(front.x, 0.5, 1e-15);
    EXPECT_NEAR(front.y, 0.5, 1e-15);
    EXPECT_NEAR(EnvironmentLight::direction_to_uv({0, 1, 0}).y, 0, 1e-15);
}

TEST(LightSampling, ConstantAndGradientSkies) {
    const EnvironmentLight constant(Rgb(0.7), Rgb(0.7));
    const Hit at = surface_at({0, 0, 0}, {0, 1, 0});
    EXPECT_EQ(constant.escaped(normalize(Vec3{1, 2, 3})), Rgb(0.7));
    EXPECT_NEAR(constant.pdf(at, {0, 1, 0}, nullptr), 1 / (4 * kPi), 1e-15);
    // Ray Tracing in One Weekend's sky: white at the nadir, (0.5, 0.7, 1) at the zenith, the mean at
    // the horizon.
    const EnvironmentLight sky(Rgb(1.0), Rgb(0.5, 0.7, 1.0));
    EXPECT_EQ(sky.escaped({0, -1, 0}), Rgb(1.0));
    EXPECT_EQ(sky.escaped({0, 1, 0}), Rgb(0.5, 0.7, 1.0));
    const Rgb horizon = sky.escaped({1, 0, 0});
    EXPECT_NEAR(horizon.r, 0.75, 1e-15);
    EXPECT_NEAR(horizon.g, 0.85, 1e-15);
    EXPECT_NEAR(horizon.b, 1.0, 1e-15);
}

TEST(LightSampling, DirectionalLightIsAnIrradiancePerCosine) {
    const DirectionalLight light({0, -1, -1}, Rgb(3.0));
    const auto s = light.sample(surface_at({5, 0, 7}, {0, 1, 0}), {0.1, 0.2});
    ASSERT_TRUE(s);
    EXPECT_LT(length(s->wi - normalize(Vec3{0, 1, 1})), 1e-15);
    EXPECT_EQ(s->radiance, Rgb(3.0));
    EXPECT_TRUE(s->delta);
    EXPECT_TRUE(s->infinite);
}

TEST(LightSampling, SpotLightFallsOffSmoothlyBetweenItsCones) {
    const SpotLight light({0, 2, 0}, {0, -1, 0}, Rgb(8.0), std::cos(radians(30)), std::cos(radians(20)));
    const auto at_angle = [&](double degrees_off_axis) {
        const double x = 2 * std::tan(radians(degrees_off_axis));
        return light.sample(surface_at({x, 0, 0}, {0, 1, 0}), {0, 0});
    };
    const auto centre = at_angle(0);
    ASSERT_TRUE(centre);
    EXPECT_NEAR(centre->radiance.r, 8.0 / 4, 1e-12);  // I / r²
    const auto inner = at_angle(19.9);
    ASSERT_TRUE(inner);
    EXPECT_NEAR(inner->radiance.r, 8.0 / length_squared(Vec3{2 * std::tan(radians(19.9)), 2, 0}), 1e-12);
    EXPECT_FALSE(at_angle(30.1));
    // Smoothstep in cos θ between the cones.
    const double t =
        (std::cos(radians(25)) - std::cos(radians(30))) / (std::cos(radians(20)) - std::cos(radians(30)));
    EXPECT_NEAR(light.falloff(std::cos(radians(25))), t * t * (3 - 2 * t), 1e-12);
    double previous = 1;
    for (double a = 20; a <= 30; a += 0.5) {  // monotonic
        const double f = light.falloff(std::cos(radians(a)));
        EXPECT_LE(f, previous);
        previous = f;
    }
}

TEST(Distribution, OneDimensionalFollowsItsWeights) {
    const Distribution1D d({1, 0, 3, 6});
    EXPECT_DOUBLE_EQ(d.integral(), 2.5);
    std::vector<double> observed(4, 0.0);
    for (int i = 0; i < 40000; ++i) {
        double pdf = 0;
        size_t cell = 0;
        const double x = d.sample(uniform_point(static_cast<std::uint64_t>(i)).x, pdf, cell);
        ASSERT_GE(x, 0);
        ASSERT_LT(x, 1);
        EXPECT_EQ(cell, static_cast<size_t>(x * 4));
        EXPECT_DOUBLE_EQ(pdf, d.pdf(x));
        observed[cell] += 1;
    }
    EXPECT_EQ(observed[1], 0);
    EXPECT_GT(test::chi2_p_value(observed, {4000, 0, 12000, 24000}), kSignificance);
    // All-zero weights: uniform, not NaN.
    const Distribution1D zero({0, 0});
    EXPECT_DOUBLE_EQ(zero.pdf(0.7), 1.0);
}

}  // namespace
}  // namespace glint
