#include "glint/sampling/pattern_stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glint {

std::vector<Point2> pattern_points(const Sampler& sampler, const SampleKey& pixel, std::uint32_t dimension) {
    std::vector<Point2> points;
    const std::uint32_t n = sampler.samples_per_pixel();
    points.reserve(n);
    SampleKey key = pixel;
    for (std::uint32_t i = 0; i < n; ++i) {
        key.sample = i;
        points.push_back(sampler.sample_2d(key, dimension));
    }
    return points;
}

double star_discrepancy_linf(const std::vector<Point2>& points) {
    const size_t n = points.size();
    if (n == 0) {
        return 1.0;
    }
    // The candidate corners: the distinct coordinates, and 1.
    std::vector<double> xs, ys;
    for (const Point2& p : points) {
        xs.push_back(p.x);
        ys.push_back(p.y);
    }
    for (auto* v : {&xs, &ys}) {
        v->push_back(1.0);
        std::sort(v->begin(), v->end());
        v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    const size_t nx = xs.size(), ny = ys.size();
    // count[i][j]: points with x ≤ xs[i] and y ≤ ys[j] (2-D prefix sums over coordinate ranks).
    std::vector<std::uint32_t> count(nx * ny, 0);
    for (const Point2& p : points) {
        const size_t i = std::lower_bound(xs.begin(), xs.end(), p.x) - xs.begin();
        const size_t j = std::lower_bound(ys.begin(), ys.end(), p.y) - ys.begin();
        ++count[i * ny + j];
    }
    for (size_t i = 0; i < nx; ++i) {
        for (size_t j = 0; j < ny; ++j) {
            std::uint32_t c = count[i * ny + j];
            if (i > 0)
                c += count[(i - 1) * ny + j];
            if (j > 0)
                c += count[i * ny + j - 1];
            if (i > 0 && j > 0)
                c -= count[(i - 1) * ny + j - 1];
            count[i * ny + j] = c;
        }
    }
    const double inv_n = 1.0 / static_cast<double>(n);
    double worst = 0;
    for (size_t i = 0; i < nx; ++i) {
        for (size_t j = 0; j < ny; ++j) {
            const double area = xs[i] * ys[j];
            // Closed box [0,a]×[0,b] (the limit of open boxes from above): too many points.
            worst = std::max(worst, count[i * ny + j] * inv_n - area);
            // Open box [0,a)×[0,b): points strictly below both coordinates, too few points.
            const std::uint32_t open = (i > 0 && j > 0) ? count[(i - 1) * ny + j - 1] : 0;
            worst = std::max(worst, area - open * inv_n);
        }
    }
    return worst;
}

double star_discrepancy_l2(const std::vector<Point2>& points) {
    // Warnock (1972): T² = 1/9 − (1/(2n)) Σ_i (1−x_i²)(1−y_i²) + (1/n²) Σ_i Σ_j
    // (1−max(x_i,x_j))(1−max(y_i,y_j)).
    const size_t n = points.size();
    if (n == 0) {
        return 1.0 / 3.0;
    }
    double single = 0, pairs = 0;
    for (size_t i = 0; i < n; ++i) {
        const Point2& p = points[i];
        single += (1 - p.x * p.x) * (1 - p.y * p.y);
        pairs += (1 - p.x) * (1 - p.y);  // the diagonal i = j
        for (size_t j = i + 1; j < n; ++j) {
            pairs += 2 * (1 - std::max(p.x, points[j].x)) * (1 - std::max(p.y, points[j].y));
        }
    }
    const double nd = static_cast<double>(n);
    return std::sqrt(std::max(0.0, 1.0 / 9.0 - single / (2 * nd) + pairs / (nd * nd)));
}

double minimum_distance(std::vector<Point2> points) {
    if (points.size() < 2) {
        return 0;
    }
    // Sweep in x: only pairs closer in x than the best distance so far can improve it.
    std::sort(points.begin(), points.end(), [](const Point2& a, const Point2& b) { return a.x < b.x; });
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < points.size(); ++i) {
        for (size_t j = i + 1; j < points.size() && points[j].x - points[i].x < best; ++j) {
            best = std::min(best, std::hypot(points[j].x - points[i].x, points[j].y - points[i].y));
        }
    }
    return best;
}

bool points_per_cell_equal(const std::vector<Point2>& points, std::uint32_t columns, std::uint32_t rows,
                           std::uint32_t per_cell) {
    if (columns == 0 || rows == 0 || points.size() != static_cast<size_t>(columns) * rows * per_cell) {
        return false;
    }
    std::vector<std::uint32_t> count(static_cast<size_t>(columns) * rows, 0);
    for (const Point2& p : points) {
        if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1)) {
            return false;
        }
        const auto cx = std::min(columns - 1, static_cast<std::uint32_t>(p.x * columns));
        const auto cy = std::min(rows - 1, static_cast<std::uint32_t>(p.y * rows));
        ++count[static_cast<size_t>(cy) * columns + cx];
    }
    return std::all_of(count.begin(), count.end(), [per_cell](std::uint32_t c) { return c == per_cell; });
}

bool satisfies_n_rooks(const std::vector<Point2>& points) {
    const auto n = static_cast<std::uint32_t>(points.size());
    return points_per_cell_equal(points, n, 1, 1) && points_per_cell_equal(points, 1, n, 1);
}

bool is_base2_net(const std::vector<Point2>& points) {
    const size_t n = points.size();
    if (n == 0 || (n & (n - 1)) != 0) {
        return false;
    }
    std::uint32_t k = 0;
    while ((size_t{1} << k) < n) {
        ++k;
    }
    for (std::uint32_t p = 0; p <= k; ++p) {
        if (!points_per_cell_equal(points, 1u << p, 1u << (k - p), 1)) {
            return false;
        }
    }
    return true;
}

}  // namespace glint
