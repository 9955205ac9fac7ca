#include "glint/sampling/regular.hpp"

#include <cmath>

#include "glint/sampling/low_discrepancy.hpp"

namespace glint {

std::uint32_t square_grid_size(std::uint32_t samples_per_pixel) {
    const std::uint64_t n = std::max(1u, samples_per_pixel);
    auto k = static_cast<std::uint64_t>(std::sqrt(static_cast<double>(n)));
    while (k * k < n) {
        ++k;
    }
    while (k > 1 && (k - 1) * (k - 1) >= n) {
        --k;
    }
    return static_cast<std::uint32_t>(k);
}

RegularSampler::RegularSampler(std::uint32_t samples_per_pixel)
    : grid_(square_grid_size(samples_per_pixel)) {}

Point2 RegularSampler::sample_2d(const SampleHashes& key, std::uint32_t dimension) const {
    const std::uint32_t n = grid_ * grid_;
    const auto scramble = static_cast<std::uint32_t>(key.pixel_bits(dimension));
    const std::uint32_t cell = permute(pattern_index(key, n), n, scramble);
    const double inv = 1.0 / grid_;
    return {(cell % grid_ + 0.5) * inv, (cell / grid_ + 0.5) * inv};
}

double RegularSampler::sample_1d(const SampleHashes& key, std::uint32_t dimension) const {
    const std::uint32_t n = grid_ * grid_;
    const auto scramble = static_cast<std::uint32_t>(key.pixel_bits(dimension) >> 32);
    return (permute(pattern_index(key, n), n, scramble) + 0.5) / n;
}

}  // namespace glint
