#include <gtest/gtest.h>

#include <cmath>

#include "glint/core/math.hpp"

namespace glint {
namespace {

// The error of sincos_quarter_pi against std::sin and std::cos, in units of the result's magnitude
// (relative for sin, whose values go to 0 with x; cos stays in [0.7, 1]).
TEST(SinCos, QuarterPiSeriesMatchesTheLibraryToTheLastBits) {
    constexpr int kSteps = 200001;
    double worst_sin = 0;
    double worst_cos = 0;
    for (int i = 0; i < kSteps; ++i) {
        const double x = (kPi / 4) * (2.0 * i / (kSteps - 1) - 1);  // −π/4 … π/4, ends included
        const SinCos sc = sincos_quarter_pi(x);
        if (x != 0) {
            worst_sin = std::max(worst_sin, std::abs(sc.sin - std::sin(x)) / std::abs(std::sin(x)));
        }
        worst_cos = std::max(worst_cos, std::abs(sc.cos - std::cos(x)));
    }
    EXPECT_LT(worst_sin, 1e-15);
    EXPECT_LT(worst_cos, 1e-15);
    EXPECT_EQ(sincos_quarter_pi(0).sin, 0.0);
    EXPECT_EQ(sincos_quarter_pi(0).cos, 1.0);
}

// The same in units in the last place of the library's result: the series' evaluation order (pairs of
// terms, Estrin's scheme) must not cost accuracy. Both it and Horner's rule measure at most 1 ulp from
// glibc here (and at most 1.4 ulps from the exact values, against long double).
TEST(SinCos, QuarterPiSeriesIsWithinAnUlpOfTheLibrary) {
    constexpr int kSteps = 200001;
    const auto ulps = [](double value, double reference) {
        const double magnitude = std::abs(reference);
        return std::abs(value - reference) / (std::nextafter(magnitude, kInf) - magnitude);
    };
    double worst_sin = 0;
    double worst_cos = 0;
    for (int i = 0; i < kSteps; ++i) {
        const double x = (kPi / 4) * (2.0 * i / (kSteps - 1) - 1);
        const SinCos sc = sincos_quarter_pi(x);
        if (x != 0) {
            worst_sin = std::max(worst_sin, ulps(sc.sin, std::sin(x)));
        }
        worst_cos = std::max(worst_cos, ulps(sc.cos, std::cos(x)));
    }
    EXPECT_LE(worst_sin, 1.5);
    EXPECT_LE(worst_cos, 1.5);
}

TEST(SinCos, TurnsMatchTheLibraryOverTheWholeCircle) {
    constexpr int kSteps = 400001;
    double worst = 0;
    for (int i = 0; i < kSteps; ++i) {
        const double turns = static_cast<double>(i) / (kSteps - 1);  // 0 … 1, every octant's ends
        const SinCos sc = sincos_turns(turns);
        const double phi = 2 * kPi * turns;
        // Absolute error: std::sin(2π u) itself is off by ~1e-16 absolutely near its zeros (2π u rounds).
        worst = std::max({worst, std::abs(sc.sin - std::sin(phi)), std::abs(sc.cos - std::cos(phi))});
    }
    EXPECT_LT(worst, 1e-15);
}

TEST(SinCos, TurnsAreExactAtQuarterTurnsAndKeepTheSignsOfEachQuadrant) {
    EXPECT_EQ(sincos_turns(0).sin, 0.0);
    EXPECT_EQ(sincos_turns(0).cos, 1.0);
    EXPECT_EQ(sincos_turns(0.25).sin, 1.0);
    EXPECT_EQ(std::abs(sincos_turns(0.25).cos), 0.0);
    EXPECT_EQ(sincos_turns(0.5).cos, -1.0);
    EXPECT_EQ(std::abs(sincos_turns(0.5).sin), 0.0);
    EXPECT_EQ(sincos_turns(0.75).sin, -1.0);
    EXPECT_EQ(std::abs(sincos_turns(0.75).cos), 0.0);
    EXPECT_EQ(sincos_turns(1).cos, 1.0);
    // Eighth turns: |sin| = |cos| = √½ (to 2 ulps), with the signs of the quadrant.
    const double h = std::sqrt(0.5);
    const double signs[4][2] = {{1, 1}, {1, -1}, {-1, -1}, {-1, 1}};
    for (int k = 0; k < 4; ++k) {
        const SinCos sc = sincos_turns(0.125 + 0.25 * k);
        EXPECT_NEAR(sc.sin, signs[k][0] * h, 2.5e-16) << k;
        EXPECT_NEAR(sc.cos, signs[k][1] * h, 2.5e-16) << k;
    }
    // Near a zero of cos, the small value is accurate relative to itself: cos(2π(¼ − ε)) = sin(2πε).
    const double eps = 1e-9;
    EXPECT_NEAR(sincos_turns(0.25 - eps).cos / std::sin(2 * kPi * eps), 1.0, 1e-7);
}

}  // namespace
}  // namespace glint
