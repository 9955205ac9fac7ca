// How fast each sample pattern's estimate of a pixel integral converges: the root mean square error
// over many pixels (each pixel a different randomisation of the pattern) of the mean of n samples of
// an integrand with a known integral, for growing n. Behind `glint samples --convergence`.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "glint/core/vec.hpp"

namespace glint {

struct TestIntegrand {
    std::string name;
    std::function<double(Point2)> f;
    double integral;  // over [0,1)², known in closed form
};

// A pixel cut by an edge: the indicator of y < c + m·x, with the irrational slope m = (√5 − 1)/2 and
// c = 0.2, whose area in the unit square is c + m/2. Jittered sampling converges as n^−3/4 here.
TestIntegrand edge_integrand();
// A smooth bump: exp(−|p − μ|²/(2σ²)), μ = (0.4, 0.55), σ = 0.25, integrated with erf.
TestIntegrand smooth_integrand();

struct ConvergenceCurve {
    std::string pattern;
    std::string integrand;
    std::vector<std::uint32_t> samples;  // as taken by the pattern (jittered and regular round up)
    std::vector<double> rmse;
    double slope = 0;  // least-squares slope of log rmse against log samples, over samples ≥ fit_from
};

// Every pattern × integrand × requested count, over pixels (0, 0) … (pixels − 1, 0) with `seed`.
std::vector<ConvergenceCurve> convergence_study(const std::vector<std::string>& patterns,
                                                const std::vector<TestIntegrand>& integrands,
                                                const std::vector<std::uint32_t>& counts,
                                                std::uint32_t pixels, std::uint64_t seed,
                                                std::uint32_t fit_from);

// The least-squares slope of log y against log x over the pairs with x ≥ fit_from.
double log_log_slope(const std::vector<std::uint32_t>& x, const std::vector<double>& y,
                     std::uint32_t fit_from);

}  // namespace glint
