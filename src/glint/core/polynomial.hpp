// Real roots of low-degree polynomials by root isolation: between consecutive roots of the derivative
// a polynomial is monotonic, so each such piece holds at most one root, found by Newton's method kept
// inside its bracket by bisection. Slower than closed forms (Ferrari's quartic) but it cannot lose a
// root to cancellation in the formula, and its accuracy is that of evaluating the polynomial.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace glint {

// p(x) = c[0] + c[1] x + … + c[n] xⁿ, by Horner's rule.
inline double polynomial_value(const double* c, int n, double x) {
    double v = c[n];
    for (int i = n - 1; i >= 0; --i) {
        v = v * x + c[i];
    }
    return v;
}

namespace detail {

// The root of p in [a, b], where p is monotonic and p(a), p(b) have opposite signs.
inline double bracketed_root(const double* c, const double* dc, int n, double a, double b,
                             bool negative_at_a) {
    double x = 0.5 * (a + b);
    for (int iteration = 0; iteration < 200; ++iteration) {
        const double fx = polynomial_value(c, n, x);
        if (fx == 0) {
            return x;
        }
        if ((fx < 0) == negative_at_a) {
            a = x;
        } else {
            b = x;
        }
        const double slope = polynomial_value(dc, n - 1, x);
        double next = slope != 0 ? x - fx / slope : 0.5 * (a + b);
        if (!(next > a && next < b)) {
            next = 0.5 * (a + b);  // Newton left the bracket: bisect instead
        }
        if (next == x ||
            b - a <= 2 * std::numeric_limits<double>::epsilon() * std::max(std::abs(a), std::abs(b))) {
            return next;
        }
        x = next;
    }
    return x;
}

}  // namespace detail

// The real roots of p(x) = c[0] + … + c[n] xⁿ (n ≤ 4, c[n] ≠ 0) in [lo, hi], ascending, written to
// `roots` (room for n). For n ≥ 3, roots of even multiplicity (the polynomial touches zero without
// crossing it) are not reported: for ray tracing they are grazing hits of measure zero. Quadratics
// are solved in closed form (a double root is reported once).
inline int polynomial_roots(const double* c, int n, double lo, double hi, double* roots) {
    if (n == 1) {
        const double x = -c[0] / c[1];
        if (x >= lo && x <= hi) {
            roots[0] = x;
            return 1;
        }
        return 0;
    }
    if (n == 2) {
        // Closed form, without cancellation (q never subtracts): only the cubic's critical points come
        // from here, and they need not be exact, only to split the cubic into monotonic pieces.
        const double discriminant = c[1] * c[1] - 4 * c[2] * c[0];
        if (discriminant < 0) {
            return 0;
        }
        const double q = -0.5 * (c[1] + std::copysign(std::sqrt(discriminant), c[1]));
        double r0 = q / c[2], r1 = q != 0 ? c[0] / q : r0;
        if (r0 > r1) {
            std::swap(r0, r1);
        }
        int count = 0;
        for (const double r : {r0, r1}) {
            if (r >= lo && r <= hi && (count == 0 || r != roots[0])) {
                roots[count++] = r;
            }
        }
        return count;
    }
    double derivative[4] = {};
    for (int i = 1; i <= n; ++i) {
        derivative[i - 1] = i * c[i];
    }
    double breaks[5] = {};
    const int critical = polynomial_roots(derivative, n - 1, lo, hi, breaks);
    breaks[critical] = hi;
    int count = 0;
    double a = lo;
    bool negative_at_a = polynomial_value(c, n, lo) < 0;
    for (int i = 0; i <= critical; ++i) {
        const double b = breaks[i];
        const bool negative_at_b = polynomial_value(c, n, b) < 0;
        if (negative_at_a != negative_at_b) {
            roots[count++] = detail::bracketed_root(c, derivative, n, a, b, negative_at_a);
        }
        a = b;
        negative_at_a = negative_at_b;
    }
    return count;
}

}  // namespace glint
