// Warps against their densities: χ² goodness-of-fit tests in the style of Nori's warptest, the
// concentric map's area preservation, and the moments the densities imply.
#include "glint/sampling/warps.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "glint/core/math.hpp"
#include "sampling/chi_square.hpp"

namespace glint {
namespace {

using test::chi2_survival;
using test::random_point;

TEST(ChiSquare, SurvivalFunctionMatchesClosedForms) {
    // k = 2: Q = e^(−x/2). k = 1: Q = erfc(√(x/2)). k = 4: Q = e^(−x/2)(1 + x/2).
    for (const double x : {0.1, 1.0, 3.0, 10.0, 40.0}) {
        EXPECT_NEAR(chi2_survival(x, 2), std::exp(-x / 2), 1e-12) << x;
        EXPECT_NEAR(chi2_survival(x, 1), std::erfc(std::sqrt(x / 2)), 1e-12) << x;
        EXPECT_NEAR(chi2_survival(x, 4), std::exp(-x / 2) * (1 + x / 2), 1e-12) << x;
    }
    // A tabulated quantile: the 99th percentile of χ² with 100 degrees of freedom is 135.807.
    EXPECT_NEAR(chi2_survival(135.807, 100), 0.01, 1e-5);
}

// The histogram of warped directions over cells equal in (cos θ, φ), i.e. equal in solid angle,
// against the integral of the claimed density over each cell.
struct Chi2Result {
    double statistic = 0;
    int degrees_of_freedom = 0;
    double p_value = 0;
    int outside = 0;  // samples outside the binned range (cos θ < z_min) or not unit length
};

constexpr int kSamples = 200000;
constexpr int kCosBins = 20;
constexpr int kPhiBins = 40;
// Significance 1% for the whole suite, split over its χ² tests (Šidák: 1 − (1 − α)^(1/m)), so that a
// correct warp with another seed would fail the suite only 1% of the time.
constexpr int kChi2Tests = 8;  // sphere, hemisphere, 4 cosine powers, cone, disk
const double kSignificance = 1 - std::pow(1 - 0.01, 1.0 / kChi2Tests);

Chi2Result chi2_directions(const std::function<Vec3(Point2)>& warp,
                           const std::function<double(const Vec3&)>& pdf, double z_min, std::uint64_t seed) {
    std::vector<double> observed(kCosBins * kPhiBins, 0);
    Chi2Result result;
    for (int i = 0; i < kSamples; ++i) {
        const Vec3 d = warp(random_point(seed, static_cast<std::uint64_t>(i)));
        if (std::abs(length(d) - 1) > 1e-12 || d.z < z_min) {
            ++result.outside;
            continue;
        }
        const int zi = std::min(kCosBins - 1, static_cast<int>((d.z - z_min) / (1 - z_min) * kCosBins));
        double phi = std::atan2(d.y, d.x);
        phi = phi < 0 ? phi + 2 * kPi : phi;
        const int pi = std::min(kPhiBins - 1, static_cast<int>(phi / (2 * kPi) * kPhiBins));
        observed[zi * kPhiBins + pi] += 1;
    }
    // Expected counts: N ∫∫ pdf d(cos θ) dφ over each cell, by Simpson's rule on a 9 × 9 grid per cell
    // (the densities are smooth inside the binned range).
    const int m = 8;
    const double dz = (1 - z_min) / kCosBins, dphi = 2 * kPi / kPhiBins;
    std::vector<double> expected(observed.size());
    for (int zi = 0; zi < kCosBins; ++zi) {
        for (int pi = 0; pi < kPhiBins; ++pi) {
            double integral = 0;
            for (int a = 0; a <= m; ++a) {
                for (int b = 0; b <= m; ++b) {
                    const double wa = (a == 0 || a == m) ? 1 : (a % 2 ? 4 : 2);
                    const double wb = (b == 0 || b == m) ? 1 : (b % 2 ? 4 : 2);
                    const double z = z_min + dz * (zi + static_cast<double>(a) / m);
                    const double phi = dphi * (pi + static_cast<double>(b) / m);
                    const double s = safe_sqrt(1 - z * z);
                    integral += wa * wb * pdf({s * std::cos(phi), s * std::sin(phi), z});
                }
            }
            expected[zi * kPhiBins + pi] = kSamples * integral * (dz / (3 * m)) * (dphi / (3 * m));
        }
    }
    // Cells expecting fewer than 5 are pooled into one, so that the χ² approximation holds.
    double pooled_observed = 0, pooled_expected = 0;
    int cells = 0;
    for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < 5) {
            pooled_observed += observed[i];
            pooled_expected += expected[i];
            continue;
        }
        result.statistic += sqr(observed[i] - expected[i]) / expected[i];
        ++cells;
    }
    if (pooled_expected > 0 || pooled_observed > 0) {
        result.statistic +=
            pooled_expected > 0 ? sqr(pooled_observed - pooled_expected) / pooled_expected : kInf;
        ++cells;
    }
    result.degrees_of_freedom = cells - 1;
    result.p_value = chi2_survival(result.statistic, result.degrees_of_freedom);
    return result;
}

void expect_fits(const Chi2Result& r) {
    EXPECT_EQ(r.outside, 0);
    EXPECT_GT(r.degrees_of_freedom, 50);
    EXPECT_GT(r.p_value, kSignificance)
        << "χ² = " << r.statistic << " with " << r.degrees_of_freedom << " degrees of freedom";
}

TEST(Warps, UniformSphereFitsItsDensity) {
    expect_fits(chi2_directions(
        square_to_uniform_sphere, [](const Vec3&) { return uniform_sphere_pdf(); }, -1, 1));
}

TEST(Warps, UniformHemisphereFitsItsDensity) {
    expect_fits(chi2_directions(
        square_to_uniform_hemisphere, [](const Vec3&) { return uniform_hemisphere_pdf(); }, 0, 2));
}

TEST(Warps, CosinePowerHemisphereFitsItsDensity) {
    for (const double e : {0.0, 1.0, 4.5, 30.0}) {
        SCOPED_TRACE(e);
        expect_fits(chi2_directions([e](Point2 u) { return square_to_cosine_power_hemisphere(u, e); },
                                    [e](const Vec3& d) { return cosine_power_hemisphere_pdf(d, e); }, 0,
                                    3 + static_cast<std::uint64_t>(e)));
    }
}

TEST(Warps, UniformConeFitsItsDensity) {
    const double cos_max = std::cos(radians(25));
    expect_fits(chi2_directions([&](Point2 u) { return square_to_uniform_cone(u, cos_max); },
                                [&](const Vec3&) { return uniform_cone_pdf(cos_max); }, cos_max, 7));
}

TEST(Warps, NarrowConeKeepsItsAngle) {
    // A cone about 1e-6 rad wide (a far, small light). 1 − cos θ is uniform in [0, 1 − cos_max), so
    // θ = 2 asin(√(x (1 − cos_max)/2)) exactly; a sine taken from 1 − cos² would be off by ~1e-3 here.
    const double cos_max = std::cos(1e-6);
    for (const double x : {0.0, 0.25, 0.5, 0.999999}) {
        const Vec3 d = square_to_uniform_cone({x, 0.3}, cos_max);
        const double theta = std::atan2(std::hypot(d.x, d.y), d.z);
        const double expected = 2 * std::asin(std::sqrt(x * (1 - cos_max) / 2));
        EXPECT_NEAR(theta, expected, 1e-9 * 1e-6) << x;
        EXPECT_NEAR(length(d), 1, 1e-15);
    }
}

TEST(Warps, ChiSquareTestRejectsASlightlyWrongDensity) {
    // The test has power: cosine-weighted samples (e = 1) against the density for e = 1.1, or the
    // points of a sphere warp fed a square squeezed by 5% along x, are rejected.
    const Chi2Result wrong_exponent =
        chi2_directions([](Point2 u) { return square_to_cosine_power_hemisphere(u, 1); },
                        [](const Vec3& d) { return cosine_power_hemisphere_pdf(d, 1.1); }, 0, 4);
    EXPECT_LT(wrong_exponent.p_value, 1e-6);
    const Chi2Result wrong_sphere = chi2_directions(
        [](Point2 u) {
            return square_to_uniform_sphere({std::pow(u.x, 1.05), u.y});
        },
        [](const Vec3&) { return uniform_sphere_pdf(); }, -1, 5);
    EXPECT_LT(wrong_sphere.p_value, 1e-6);
}

TEST(Warps, PdfsIntegrateToOne) {
    // ∫ pdf dω = 2π ∫ pdf(z) dz for densities symmetric about +z (Simpson, 2000 intervals).
    const auto integrate = [](const std::function<double(double)>& f, double lo, double hi) {
        const int n = 2000;
        const double h = (hi - lo) / n;
        double s = f(lo) + f(hi);
        for (int i = 1; i < n; ++i) {
            s += (i % 2 ? 4 : 2) * f(lo + i * h);
        }
        return 2 * kPi * s * h / 3;
    };
    EXPECT_NEAR(integrate([](double) { return uniform_sphere_pdf(); }, -1, 1), 1, 1e-12);
    EXPECT_NEAR(integrate([](double) { return uniform_hemisphere_pdf(); }, 0, 1), 1, 1e-12);
    EXPECT_NEAR(integrate([](double) { return uniform_cone_pdf(0.3); }, 0.3, 1), 1, 1e-12);
    for (const double e : {0.0, 1.0, 2.0, 7.0, 100.0}) {
        EXPECT_NEAR(integrate(
                        [e](double z) {
                            return cosine_power_hemisphere_pdf({0, 0, z}, e);
                        },
                        0, 1),
                    1, 1e-6)
            << e;
    }
    EXPECT_EQ(cosine_power_hemisphere_pdf({0, 0, -1}, 1), 0);
    EXPECT_NEAR(uniform_disk_pdf() * kPi, 1, 1e-15);
}

TEST(Warps, MeanCosineUnderCosinePowerIsEPlusOneOverEPlusTwo) {
    // E[cos θ] = ∫₀¹ z (e+1) z^e dz = (e+1)/(e+2).
    for (const double e : {0.0, 1.0, 3.0, 20.0}) {
        double sum = 0, sum_sq = 0;
        const int n = 100000;
        for (int i = 0; i < n; ++i) {
            const double z = square_to_cosine_power_hemisphere(random_point(11, i), e).z;
            sum += z;
            sum_sq += z * z;
        }
        const double mean = sum / n;
        const double standard_error = std::sqrt((sum_sq / n - mean * mean) / n);
        EXPECT_NEAR(mean, (e + 1) / (e + 2), 4 * standard_error) << e;
    }
}

TEST(Warps, ConcentricMapFillsTheDiskKeepsItsEdgeAndCentre) {
    EXPECT_EQ(square_to_disk_concentric({0.5, 0.5}), Point2(0, 0));
    for (int i = 0; i <= 100; ++i) {
        const double t = i / 100.0;
        // The square's boundary goes to the unit circle.
        for (const Point2 u : {Point2{t, 0}, Point2{t, 1}, Point2{0, t}, Point2{1, t}}) {
            const Point2 p = square_to_disk_concentric(u);
            EXPECT_NEAR(std::hypot(p.x, p.y), 1, 1e-12);
        }
    }
    for (int i = 0; i < 10000; ++i) {
        const Point2 p = square_to_disk_concentric(random_point(12, i));
        EXPECT_LE(std::hypot(p.x, p.y), 1 + 1e-15);
    }
    // The concentric squares become concentric circles: |2u − 1|_∞ is the radius.
    const Point2 p = square_to_disk_concentric({0.8, 0.35});
    EXPECT_NEAR(std::hypot(p.x, p.y), 0.6, 1e-12);
}

TEST(Warps, ConcentricMapPreservesArea) {
    // |det J| = π everywhere (the unit square's area 1 onto the disk's π), by central differences at
    // points away from the diagonals where the map's formula switches.
    const double h = 1e-6;
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
        const Point2 u = random_point(13, i);
        const double a = 2 * u.x - 1, b = 2 * u.y - 1;
        if (std::abs(std::abs(a) - std::abs(b)) < 4 * h || std::min(u.x, u.y) < h ||
            std::max(u.x, u.y) > 1 - h) {
            continue;
        }
        const Point2 px0 = square_to_disk_concentric({u.x - h, u.y}),
                     px1 = square_to_disk_concentric({u.x + h, u.y});
        const Point2 py0 = square_to_disk_concentric({u.x, u.y - h}),
                     py1 = square_to_disk_concentric({u.x, u.y + h});
        const double dxdu = (px1.x - px0.x) / (2 * h), dydu = (px1.y - px0.y) / (2 * h);
        const double dxdv = (py1.x - py0.x) / (2 * h), dydv = (py1.y - py0.y) / (2 * h);
        EXPECT_NEAR(std::abs(dxdu * dydv - dydu * dxdv), kPi, 1e-5) << u.x << ", " << u.y;
        ++checked;
    }
    EXPECT_GT(checked, 1900);
    // Globally, equal-area annuli × sectors receive equal shares: the χ² test below.
}

TEST(Warps, ConcentricMapFitsTheUniformDiskDensity) {
    // χ² in equal-area polar cells (16 annuli equal in r² × 32 sectors): each expects N/cells. With the
    // Jacobian test above, this checks that the map is area-preserving both locally and globally.
    const int rings = 16, sectors = 32, cells = rings * sectors;
    std::vector<double> observed(cells, 0);
    for (int i = 0; i < kSamples; ++i) {
        const Point2 p = square_to_disk_concentric(random_point(14, i));
        const int ring = std::min(rings - 1, static_cast<int>((p.x * p.x + p.y * p.y) * rings));
        double phi = std::atan2(p.y, p.x);
        phi = phi < 0 ? phi + 2 * kPi : phi;
        const int sector = std::min(sectors - 1, static_cast<int>(phi / (2 * kPi) * sectors));
        observed[ring * sectors + sector] += 1;
    }
    const double expected = static_cast<double>(kSamples) / cells;
    double statistic = 0;
    for (const double o : observed) {
        statistic += sqr(o - expected) / expected;
    }
    EXPECT_GT(chi2_survival(statistic, cells - 1), kSignificance) << statistic;
}

}  // namespace
}  // namespace glint
