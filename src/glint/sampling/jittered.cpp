#include "glint/sampling/jittered.hpp"

#include <algorithm>

#include "glint/sampling/low_discrepancy.hpp"
#include "glint/sampling/regular.hpp"

namespace glint {

JitteredSampler::JitteredSampler(std::uint32_t samples_per_pixel)
    : grid_(square_grid_size(samples_per_pixel)),
      inverse_grid_(1.0 / grid_),
      inverse_count_(1.0 / (grid_ * grid_)) {}

Point2 JitteredSampler::sample_2d(const SampleHashes& key, std::uint32_t dimension) const {
    const std::uint32_t n = grid_ * grid_;
    // Which cell sample i falls in is shuffled per pixel and per dimension, so that the film position
    // and the lens position of one sample are not correlated (pbrt's "padding" of 2-D patterns).
    const auto scramble = static_cast<std::uint32_t>(key.pixel_bits(dimension));
    const std::uint32_t cell = permute(pattern_index(key, n), n, scramble);
    const Point2 jitter = unit_pair(key.sample_bits(dimension));
    // (cell + jitter)/k can round up to exactly 1 in floating point; keep the point inside [0,1).
    const double x = std::min((cell % grid_ + jitter.x) * inverse_grid_, kOneMinusEpsilon);
    const double y = std::min((cell / grid_ + jitter.y) * inverse_grid_, kOneMinusEpsilon);
    return {x, y};
}

double JitteredSampler::sample_1d(const SampleHashes& key, std::uint32_t dimension) const {
    const std::uint32_t n = grid_ * grid_;
    // The other half of the dimension's bits: a stream never draws 1-D and 2-D from one dimension, but
    // a test comparing the two should not see one shuffle.
    const auto scramble = static_cast<std::uint32_t>(key.pixel_bits(dimension) >> 32);
    const std::uint32_t stratum = permute(pattern_index(key, n), n, scramble);
    const double jitter = bits_to_unit(static_cast<std::uint32_t>(key.sample_bits(dimension)));
    return std::min((stratum + jitter) * inverse_count_, kOneMinusEpsilon);
}

}  // namespace glint
