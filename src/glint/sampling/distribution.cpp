#include "glint/sampling/distribution.hpp"

#include <algorithm>

#include "glint/core/math.hpp"
#include "glint/sampling/low_discrepancy.hpp"

namespace glint {

Distribution1D::Distribution1D(std::vector<double> weights) : weights_(std::move(weights)) {
    if (weights_.empty()) {
        weights_.push_back(1);
    }
    const std::size_t n = weights_.size();
    cdf_.resize(n + 1);
    cdf_[0] = 0;
    for (std::size_t i = 0; i < n; ++i) {
        cdf_[i + 1] = cdf_[i] + weights_[i] / static_cast<double>(n);
    }
    integral_ = cdf_[n];
    if (integral_ <= 0) {
        // Nothing to prefer: sample uniformly (weights all 1 keep pdf() consistent with sample()).
        std::fill(weights_.begin(), weights_.end(), 1.0);
        for (std::size_t i = 0; i <= n; ++i) {
            cdf_[i] = static_cast<double>(i) / static_cast<double>(n);
        }
        integral_ = 0;
    } else {
        for (double& c : cdf_) {
            c /= integral_;
        }
    }
    cdf_[n] = 1;
}

double Distribution1D::sample(double u, double& pdf, std::size_t& cell) const {
    // The last cell whose cdf start is ≤ u; cells of zero weight have equal ends and are never chosen.
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u);
    const std::size_t n = weights_.size();
    cell = std::min<std::size_t>(
        n - 1, static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, it - cdf_.begin() - 1)));
    const double width = cdf_[cell + 1] - cdf_[cell];
    const double offset = width > 0 ? (u - cdf_[cell]) / width : 0.5;
    const double mean = integral_ > 0 ? integral_ : 1.0;
    pdf = weights_[cell] / mean;
    const double x = (static_cast<double>(cell) + std::clamp(offset, 0.0, 1.0)) / static_cast<double>(n);
    return std::min(x, kOneMinusEpsilon);
}

double Distribution1D::pdf(double x) const {
    const std::size_t n = weights_.size();
    const auto cell =
        std::min<std::size_t>(n - 1, static_cast<std::size_t>(std::max(0.0, x) * static_cast<double>(n)));
    const double mean = integral_ > 0 ? integral_ : 1.0;
    return weights_[cell] / mean;
}

namespace {
std::vector<double> row_sums(const std::vector<double>& weights, std::size_t width, std::size_t height) {
    std::vector<double> sums(height, 0.0);
    for (std::size_t y = 0; y < height; ++y) {
        for (std::size_t x = 0; x < width; ++x) {
            sums[y] += weights[y * width + x];
        }
        sums[y] /= static_cast<double>(width);
    }
    return sums;
}
}  // namespace

Distribution2D::Distribution2D(const std::vector<double>& weights, std::size_t width, std::size_t height)
    : marginal_(row_sums(weights, width, height)) {
    conditional_.reserve(height);
    for (std::size_t y = 0; y < height; ++y) {
        conditional_.emplace_back(
            std::vector<double>(weights.begin() + static_cast<std::ptrdiff_t>(y * width),
                                weights.begin() + static_cast<std::ptrdiff_t>((y + 1) * width)));
    }
}

Point2 Distribution2D::sample(Point2 u, double& pdf) const {
    double pdf_row = 0;
    double pdf_column = 0;
    std::size_t row = 0;
    std::size_t column = 0;
    const double v = marginal_.sample(u.y, pdf_row, row);
    const double x = conditional_[row].sample(u.x, pdf_column, column);
    pdf = pdf_row * pdf_column;
    return {x, v};
}

double Distribution2D::pdf(Point2 p) const {
    const std::size_t rows = conditional_.size();
    const auto row = std::min<std::size_t>(
        rows - 1, static_cast<std::size_t>(std::max(0.0, p.y) * static_cast<double>(rows)));
    return marginal_.pdf(p.y) * conditional_[row].pdf(p.x);
}

}  // namespace glint
