#include "glint/sampling/multijittered.hpp"

#include <algorithm>

#include "glint/sampling/low_discrepancy.hpp"
#include "glint/sampling/regular.hpp"

namespace glint {

MultiJitteredSampler::MultiJitteredSampler(std::uint32_t samples_per_pixel) {
    const std::uint32_t n = std::max(1u, samples_per_pixel);
    std::uint32_t m = square_grid_size(n);
    while (std::uint64_t{m} * m > n || n % m != 0) {
        --m;
    }
    columns_ = m;
    rows_ = n / m;
}

Point2 MultiJitteredSampler::sample_2d(const SampleHashes& key, std::uint32_t dimension) const {
    const std::uint32_t m = columns_, r = rows_, n = m * r;
    const std::uint64_t pattern = key.pixel_bits(dimension);
    const auto p = static_cast<std::uint32_t>(pattern);
    const auto q = static_cast<std::uint32_t>(pattern >> 32);
    // Which coarse cell sample `key.sample()` fills is shuffled, so sample indices are not ordered in space.
    const std::uint32_t s = permute(pattern_index(key, n), n, p * 0x51633e2du);
    const std::uint32_t column = s % m, row = s / m;
    // Inside coarse cell (column, row), the point takes fine column column·r + σ(row) and fine row
    // row·m + τ(column): σ, τ bijections, so every fine row and column is used once (n-rooks). Sharing
    // σ along a column and τ along a row is Kensler's correlation, which spreads points more evenly.
    const std::uint32_t sub_x = permute(row, r, q * 0x02e5be93u);
    const std::uint32_t sub_y = permute(column, m, q * 0x68bc21ebu);
    const Point2 jitter = unit_pair(key.sample_bits(dimension));
    // One division of (fine stratum + jitter) keeps the point inside its fine cell in floating point.
    const double x = (column * r + sub_x + jitter.x) / n;
    const double y = (row * m + sub_y + jitter.y) / n;
    return {std::min(x, kOneMinusEpsilon), std::min(y, kOneMinusEpsilon)};
}

}  // namespace glint
