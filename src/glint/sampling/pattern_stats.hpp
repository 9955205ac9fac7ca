// Measures of a point set in the unit square: how evenly a sample pattern covers the pixel. Used by
// `glint samples --stats` and by the sampling tests.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "glint/core/vec.hpp"
#include "glint/sampling/sampler.hpp"

namespace glint {

// The n points one pixel gets from `sampler` in `dimension` (samples 0 … n−1 of the pixel).
std::vector<Point2> pattern_points(const Sampler& sampler, const SampleKey& pixel,
                                   std::uint32_t dimension = 0);

// The L∞ star discrepancy sup over boxes [0,a)×[0,b) of |#points inside / n − ab|, exactly: the
// supremum is reached at box corners on the points' coordinates, so O(n²) time and memory.
double star_discrepancy_linf(const std::vector<Point2>& points);

// The L2 star discrepancy (the root mean square of the same difference over all a, b), by Warnock's
// closed form in O(n²) time and O(1) memory.
double star_discrepancy_l2(const std::vector<Point2>& points);

// The smallest Euclidean distance between two points (0 for fewer than two points... or duplicates).
double minimum_distance(std::vector<Point2> points);

// True when the columns × rows grid over [0,1)² has exactly `per_cell` points in every cell.
bool points_per_cell_equal(const std::vector<Point2>& points, std::uint32_t columns, std::uint32_t rows,
                           std::uint32_t per_cell = 1);

// The n-rooks condition: one point in each row and each column of the n × n grid.
bool satisfies_n_rooks(const std::vector<Point2>& points);

// True when n = 2^k points form a (0, k, 2)-net in base 2: one point in every elementary interval
// [a/2^p, (a+1)/2^p) × [b/2^q, (b+1)/2^q) with p + q = k.
bool is_base2_net(const std::vector<Point2>& points);

}  // namespace glint
