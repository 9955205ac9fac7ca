// Piecewise-constant distributions for importance sampling tabulated functions (pbrt-v4 §A.1, §A.5):
// a 1-D one over [0, 1) from n non-negative weights, and a 2-D one over [0, 1)² built from a marginal
// distribution over rows and a conditional distribution per row.
#pragma once

#include <cstddef>
#include <vector>

#include "glint/core/vec.hpp"

namespace glint {

class Distribution1D {
  public:
    // Weights must be finite and non-negative; all zero gives the uniform distribution.
    explicit Distribution1D(std::vector<double> weights);

    // A point x in [0, 1) with density pdf(x) = weight[i] / mean weight on cell i; `cell` receives i.
    double sample(double u, double& pdf, std::size_t& cell) const;
    // Density at x in [0, 1).
    double pdf(double x) const;
    // Sum of weights / n: the integral of the tabulated function over [0, 1).
    double integral() const { return integral_; }
    std::size_t size() const { return weights_.size(); }

  private:
    std::vector<double> weights_;
    std::vector<double> cdf_;  // size n + 1, cdf_[0] = 0, cdf_[n] = 1
    double integral_ = 0;
};

class Distribution2D {
  public:
    // `weights` holds height rows of width values, row-major; row y covers v in [y/height, (y+1)/height).
    Distribution2D(const std::vector<double>& weights, std::size_t width, std::size_t height);

    // A point (u, v) in [0, 1)² with density pdf(point) per unit area of the square.
    Point2 sample(Point2 u, double& pdf) const;
    double pdf(Point2 p) const;

  private:
    std::vector<Distribution1D> conditional_;  // one per row
    Distribution1D marginal_;                  // over rows
};

}  // namespace glint
