// The χ² goodness-of-fit helpers of the sampling tests (warps, pixel filters): a deterministic stream
// of independent points of the unit square, and the survival function of the χ² distribution.
#pragma once

#include <cmath>
#include <cstdint>

#include "glint/core/hash.hpp"
#include "glint/core/vec.hpp"

namespace glint::test {

// A fixed, well-mixed stream of points of the unit square: the test is deterministic, and these
// points are independent (not stratified), which is what the χ² test assumes.
inline Point2 random_point(std::uint64_t seed, std::uint64_t i) {
    return {to_unit_double(hash_values(seed, i, 0)), to_unit_double(hash_values(seed, i, 1))};
}

// The regularised upper incomplete gamma function Q(a, x) = Γ(a, x)/Γ(a): the χ² survival function
// with k degrees of freedom is Q(k/2, x/2). A series below x = a + 1, a continued fraction above
// (evaluated with the modified Lentz method), as in the standard treatments.
inline double upper_incomplete_gamma_q(double a, double x) {
    if (x <= 0) {
        return 1;
    }
    const double log_prefactor = a * std::log(x) - x - std::lgamma(a);
    if (x < a + 1) {
        // P(a, x) = x^a e^−x / Γ(a) · Σ_n x^n / (a (a+1) … (a+n)).
        double term = 1 / a, sum = term;
        for (int n = 1; n < 10000 && std::abs(term) > 1e-16 * std::abs(sum); ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return 1 - sum * std::exp(log_prefactor);
    }
    // Q(a, x) = x^a e^−x / Γ(a) · 1/(x + 1 − a − 1·(1−a)/(x + 3 − a − 2·(2−a)/(x + 5 − a − …))).
    const double tiny = 1e-300;
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        const double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        d = std::abs(d) < tiny ? tiny : d;
        c = b + an / c;
        c = std::abs(c) < tiny ? tiny : c;
        d = 1 / d;
        const double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1) < 1e-16) {
            break;
        }
    }
    return std::exp(log_prefactor) * h;
}

inline double chi2_survival(double statistic, int degrees_of_freedom) {
    return upper_incomplete_gamma_q(0.5 * degrees_of_freedom, 0.5 * statistic);
}

}  // namespace glint::test
