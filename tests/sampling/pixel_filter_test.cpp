// Pixel filters (render.filter): the warps against their densities by χ², their moments, their
// stratification, the box's identity, the scene keys, and an image whose values the filter's footprint
// gives in closed form (an edge seen through an orthographic camera).
#include "glint/sampling/pixel_filter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <functional>
#include <vector>

#include "glint/scene/scene_set.hpp"
#include "sampling/chi_square.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

using test::chi2_survival;
using test::random_point;

PixelFilter tent(double radius, int subpixels = 1) {
    return {PixelFilterType::tent, radius, subpixels};
}

// The CDFs the footprints must have per axis, in pixels from the pixel's corner, written from their
// definitions rather than from the warp.

// A tent (triangle) of half-width r about c: density (1 − |x − c|/r)/r.
double tent_cdf(double x, double c, double r) {
    if (x <= c - r) {
        return 0;
    }
    if (x >= c + r) {
        return 1;
    }
    return x < c ? 0.5 * std::pow((x - (c - r)) / r, 2) : 1 - 0.5 * std::pow((c + r - x) / r, 2);
}

// The mean of the tents of half-width r about the centres of s sub-pixels, (k + ½)/s.
double subpixel_tents_cdf(double x, double r, int s) {
    double sum = 0;
    for (int k = 0; k < s; ++k) {
        sum += tent_cdf(x, (k + 0.5) / s, r);
    }
    return sum / s;
}

// smallpt's footprint, the trapezoid: density rising linearly from 0 at −¼ to 1 at ¼, 1 up to ¾, and
// falling to 0 at 1¼ (area ½·½ + ½ + ½·½ = 1).
double smallpt_trapezoid_cdf(double x) {
    if (x <= -0.25) {
        return 0;
    }
    if (x <= 0.25) {
        return std::pow(x + 0.25, 2);
    }
    if (x <= 0.75) {
        return x;  // ¼ at ¼, rising by 1 per pixel
    }
    if (x <= 1.25) {
        return 1 - std::pow(1.25 - x, 2);
    }
    return 1;
}

// χ² of the 2-D histogram of offsets over [lo, hi]² (bins × bins cells) against the separable density
// whose per-axis CDF is `cdf`: expected counts N·ΔF(x)·ΔF(y), cells expecting fewer than 5 pooled.
// Returns the p-value; an offset outside [lo, hi]² counts as impossible (p = 0).
constexpr int kSamples = 200000;
constexpr int kBins = 16;
// Significance 1% for the whole suite, split over its χ² tests that should pass (Šidák).
constexpr int kChi2Tests = 4;
const double kSignificance = 1 - std::pow(1 - 0.01, 1.0 / kChi2Tests);

double chi2_p_value(const PixelFilter& filter, const std::function<double(double)>& cdf, double lo, double hi,
                    std::uint64_t seed) {
    std::vector<double> observed(kBins * kBins, 0);
    const double width = (hi - lo) / kBins;
    for (int i = 0; i < kSamples; ++i) {
        const Point2 p = filter.offset(random_point(seed, static_cast<std::uint64_t>(i)));
        if (!(p.x >= lo && p.x <= hi && p.y >= lo && p.y <= hi)) {
            return 0;
        }
        const int bx = std::min(kBins - 1, static_cast<int>((p.x - lo) / width));
        const int by = std::min(kBins - 1, static_cast<int>((p.y - lo) / width));
        observed[by * kBins + bx] += 1;
    }
    std::vector<double> bin_probability(kBins);
    for (int b = 0; b < kBins; ++b) {
        bin_probability[b] = cdf(lo + (b + 1) * width) - cdf(lo + b * width);
    }
    double statistic = 0, pooled_observed = 0, pooled_expected = 0;
    int cells = 0;
    for (int by = 0; by < kBins; ++by) {
        for (int bx = 0; bx < kBins; ++bx) {
            const double expected = kSamples * bin_probability[bx] * bin_probability[by];
            const double seen = observed[by * kBins + bx];
            if (expected < 5) {
                pooled_observed += seen;
                pooled_expected += expected;
                continue;
            }
            statistic += (seen - expected) * (seen - expected) / expected;
            ++cells;
        }
    }
    if (pooled_expected > 0) {
        statistic +=
            (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
        ++cells;
    }
    return chi2_survival(statistic, cells - 1);
}

TEST(PixelFilter, BoxIsTheIdentity) {
    const PixelFilter box;  // the default
    EXPECT_EQ(box.type, PixelFilterType::box);
    for (int i = 0; i < 1000; ++i) {
        const Point2 u = random_point(7, static_cast<std::uint64_t>(i));
        const Point2 p = box.offset(u);
        EXPECT_EQ(std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(u.x));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(p.y), std::bit_cast<std::uint64_t>(u.y));
    }
}

TEST(PixelFilter, TentInverseCdfIsSmallptsWarp) {
    // The ends, the middle, and the quartiles: F(t) = (1 + t)²/2 below 0, so F⁻¹(¼) = √½ − 1.
    EXPECT_EQ(tent_inverse_cdf(0), -1);
    EXPECT_EQ(tent_inverse_cdf(0.5), 0);
    EXPECT_NEAR(tent_inverse_cdf(0.25), std::sqrt(0.5) - 1, 1e-15);
    EXPECT_NEAR(tent_inverse_cdf(0.75), 1 - std::sqrt(0.5), 1e-15);
    EXPECT_LT(tent_inverse_cdf(1 - 0x1.0p-53), 1);
    EXPECT_GT(tent_inverse_cdf(1 - 0x1.0p-53), 1 - 1e-7);
}

TEST(PixelFilter, TentFitsTheTriangleDensity) {
    EXPECT_GT(chi2_p_value(
                  tent(1), [](double x) { return tent_cdf(x, 0.5, 1); }, -0.5, 1.5, 1),
              kSignificance);
    EXPECT_GT(chi2_p_value(
                  tent(2.5), [](double x) { return tent_cdf(x, 0.5, 2.5); }, -2, 3, 2),
              kSignificance);
}

TEST(PixelFilter, SmallptsSubpixelTentsFitTheTrapezoid) {
    EXPECT_GT(chi2_p_value(tent(0.5, 2), smallpt_trapezoid_cdf, -0.25, 1.25, 3), kSignificance);
}

TEST(PixelFilter, SubpixelTentsFitTheMeanOfTheirTents) {
    EXPECT_GT(chi2_p_value(
                  tent(0.7, 3), [](double x) { return subpixel_tents_cdf(x, 0.7, 3); }, 1.0 / 6 - 0.7,
                  5.0 / 6 + 0.7, 4),
              kSignificance);
}

TEST(PixelFilter, ChiSquareTestRejectsANearbyFootprint) {
    // A single tent of half-width ¾ has the trapezoid's support and mean; its peak is what differs.
    EXPECT_LT(chi2_p_value(tent(0.75), smallpt_trapezoid_cdf, -0.25, 1.25, 5), 1e-6);
    // And the trapezoid is not a tent of half-width ¾.
    EXPECT_LT(chi2_p_value(
                  tent(0.5, 2), [](double x) { return tent_cdf(x, 0.5, 0.75); }, -0.25, 1.25, 6),
              1e-6);
}

// Mean and variance per axis over a midpoint grid of u (exact for the mean: the warps are antisymmetric
// about u = ½; the variance within the midpoint rule's error, largest at the tents' ends where the
// inverse CDF has a square-root slope).
TEST(PixelFilter, MeanIsThePixelCentreAndVarianceTheFootprints) {
    struct Case {
        PixelFilter filter;
        double variance;
    };
    // Box: 1/12. Tent of half-width r: r²/6. s sub-pixel tents: the sub-pixel centres' variance
    // (1 − 1/s²)/12 plus the tent's.
    const Case cases[] = {
        {PixelFilter{}, 1.0 / 12},
        {tent(1), 1.0 / 6},
        {tent(2.5), 2.5 * 2.5 / 6},
        {tent(0.5, 2), (1 - 0.25) / 12 + 0.25 / 6},  // smallpt's: 1/16 + 1/24
        {tent(0.7, 3), (1 - 1.0 / 9) / 12 + 0.49 / 6},
    };
    constexpr int n = 3 << 13;  // every sub-pixel's share of u holds whole cells of the grid
    for (const Case& c : cases) {
        double sum_x = 0, sum_y = 0, sum_squares = 0;
        for (int i = 0; i < n; ++i) {
            const double u = (i + 0.5) / n;
            const Point2 p = c.filter.offset({u, 1 - u});
            sum_x += p.x;
            sum_y += p.y;
            sum_squares += (p.x - 0.5) * (p.x - 0.5);
        }
        EXPECT_NEAR(sum_x / n, 0.5, 1e-12) << c.filter.radius << " " << c.filter.subpixels;
        EXPECT_NEAR(sum_y / n, 0.5, 1e-12) << c.filter.radius << " " << c.filter.subpixels;
        EXPECT_NEAR(sum_squares / n, c.variance, 1e-5 * c.variance)
            << c.filter.radius << " " << c.filter.subpixels;
    }
}

TEST(PixelFilter, KeepsStrataCompactWithinOneSubpixel) {
    // Along u, the offset rises within each sub-pixel's share of [0, 1) and stays inside its tent: a
    // stratum of u becomes one interval of one sub-pixel's tent.
    for (const PixelFilter& filter : {tent(1), tent(0.5, 2), tent(0.7, 3)}) {
        const int s = filter.subpixels;
        constexpr int n = 3 * 4096;
        double previous = -1e9;
        int previous_cell = -1;
        for (int i = 0; i < n; ++i) {
            const double u = (i + 0.5) / n;
            const int cell = static_cast<int>(u * s);
            const double x = filter.offset({u, u}).x;
            const double centre = (cell + 0.5) / s;
            EXPECT_GE(x, centre - filter.radius);
            EXPECT_LE(x, centre + filter.radius);
            if (cell == previous_cell) {
                EXPECT_GT(x, previous) << u;
            }
            previous = x, previous_cell = cell;
        }
    }
    // The ends of [0, 1): the first sub-pixel's left end, and the last's right end without reaching it.
    const PixelFilter thirds = tent(1, 3);
    EXPECT_EQ(thirds.offset({0, 0}).x, 1.0 / 6 - 1);
    const double last = thirds.offset({1 - 0x1.0p-53, 0}).x;
    EXPECT_LT(last, 5.0 / 6 + 1);
    EXPECT_GT(last, 5.0 / 6 + 1 - 1e-6);
}

TEST(PixelFilter, SceneKeysAndTheirErrors) {
    const auto filter_of = [](const std::string& render) {
        return test::scene_from_text("render: " + render + "\n").view.settings.filter;
    };
    EXPECT_EQ(filter_of("{width: 4, height: 4}"), PixelFilter{});
    EXPECT_EQ(filter_of("{filter: box}"), PixelFilter{});
    EXPECT_EQ(filter_of("{filter: tent}"), tent(1));
    EXPECT_EQ(filter_of("{filter: {type: tent, radius: 0.5, subpixels: 2}}"), tent(0.5, 2));

    const auto error_of = [](const std::string& render) {
        try {
            test::scene_from_text("render: " + render + "\n");
        } catch (const SceneError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(error_of("{filter: tnet}").find("did you mean 'tent'"), std::string::npos)
        << error_of("{filter: tnet}");
    EXPECT_NE(error_of("{filter: {type: tent, radius: 0}}").find("radius must be greater than zero"),
              std::string::npos);
    EXPECT_NE(error_of("{filter: {type: tent, subpixels: 1025}}").find("more than 1024"), std::string::npos);
    EXPECT_NE(error_of("{filter: {type: tent, subpixels: 0}}").find("subpixels"), std::string::npos);
    // A box has no keys: its radius would be silently ignored otherwise.
    EXPECT_NE(error_of("{filter: {type: box, radius: 2}}").find("unknown key 'radius'"), std::string::npos)
        << error_of("{filter: {type: box, radius: 2}}");
}

TEST(PixelFilter, SetOnTheCommandLine) {
    SceneDesc desc = parse_scene_text("render: {width: 4, height: 4}\n", "test.yaml", ".");
    apply_set(desc, "render.filter.type=tent");
    apply_set(desc, "render.filter.subpixels=2");
    EXPECT_EQ(build_view(desc).settings.filter, tent(1, 2));
    // A plain word becomes a map when a key is set below it.
    SceneDesc word = parse_scene_text("render: {filter: tent}\n", "test.yaml", ".");
    apply_set(word, "render.filter.radius=0.5");
    EXPECT_EQ(build_view(word).settings.filter, tent(0.5));
}

// An edge seen through an orthographic camera, black box left of it, white background right: column
// j's value is the share of its footprint right of the edge, 1 − F(edge − j) with F the footprint's
// per-axis CDF from the pixel's corner, whatever the rows do (the box spans every row's footprint).
std::vector<double> edge_columns(const std::string& filter) {
    constexpr int kWidth = 8, kHeight = 2;
    // Sobol's 1024 points take each of 1024 intervals of x once, and the filter warps x monotonically
    // (per sub-pixel), so the share of a pixel's samples beyond the edge is off by ~1/1024 at most.
    const std::string scene =
        "render: {width: 8, height: 2, samples: 1024, sampler: sobol, integrator: raycast, filter: " +
        filter +
        "}\n"
        "camera: {type: orthographic, eye: [0, 0, 5], look_at: [0, 0, 0], up: [0, 1, 0], height: 1}\n"
        "background: 1\n"
        "objects:\n"
        "  - {type: box, min: [-10, -10, -1], max: [0, 10, 0], material: {type: matte, albedo: 0}}\n";
    const Image image = test::render_film(test::scene_from_text(scene)).to_image();
    std::vector<double> columns(kWidth, 0);
    for (int x = 0; x < kWidth; ++x) {
        for (int y = 0; y < kHeight; ++y) {
            columns[x] += image.pixel(x, y)[1] / kHeight;
        }
    }
    return columns;
}

TEST(PixelFilter, AnEdgeIsBlurredByExactlyTheFootprint) {
    constexpr double kEdge = 4;  // world x = 0, the film's middle: a pixel boundary
    const auto expect_columns = [&](const std::string& filter, const std::function<double(double)>& cdf) {
        const std::vector<double> columns = edge_columns(filter);
        for (int x = 0; x < static_cast<int>(columns.size()); ++x) {
            EXPECT_NEAR(columns[x], 1 - cdf(kEdge - x), 0.004) << filter << ", column " << x;
        }
    };
    // Box: a sharp edge. Tent of half-width 1: the columns beside the edge see ⅛ of the other side.
    expect_columns("box", [](double x) { return std::clamp(x, 0.0, 1.0); });
    expect_columns("tent", [](double x) { return tent_cdf(x, 0.5, 1); });
    expect_columns("{type: tent, radius: 2.5}", [](double x) { return tent_cdf(x, 0.5, 2.5); });
    // smallpt's: 1/16 of the other side.
    expect_columns("{type: tent, radius: 0.5, subpixels: 2}", smallpt_trapezoid_cdf);
}

}  // namespace
}  // namespace glint
