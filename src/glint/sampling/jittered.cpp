#include "glint/sampling/jittered.hpp"

#include "glint/sampling/regular.hpp"

#include <algorithm>
#include <cmath>

namespace glint {

JitteredSampler::JitteredSampler(std::uint32_t samples_per_pixel)
    : grid_(square_grid_size(samples_per_pixel)) {}

Point2 JitteredSampler::sample_2d(const SampleKey& key, std::uint32_t dimension) const {
    const std::uint32_t n = grid_ * grid_;
    // Which cell sample i falls in is shuffled per pixel and per dimension, so that the film position
    // and the lens position of one sample are not correlated (pbrt's "padding" of 2-D patterns).
    const auto scramble =
        static_cast<std::uint32_t>(hash_values(key.seed, key.pixel_x, key.pixel_y, dimension, 0x6a17u));
    const std::uint32_t cell = permute(key.sample % n, n, scramble);
    const double jx = key.uniform(2 * dimension);
    const double jy = key.uniform(2 * dimension + 1);
    const double inv = 1.0 / grid_;
    // (cell + jitter)/k can round up to exactly 1 in floating point; keep the point inside [0,1).
    const double x = std::min((cell % grid_ + jx) * inv, 0x1.fffffffffffffp-1);
    const double y = std::min((cell / grid_ + jy) * inv, 0x1.fffffffffffffp-1);
    return {x, y};
}

double JitteredSampler::sample_1d(const SampleKey& key, std::uint32_t dimension) const {
    const std::uint32_t n = grid_ * grid_;
    const auto scramble =
        static_cast<std::uint32_t>(hash_values(key.seed, key.pixel_x, key.pixel_y, dimension, 0x6a18u));
    const std::uint32_t stratum = permute(key.sample % n, n, scramble);
    return std::min((stratum + key.uniform(2 * dimension)) / n, 0x1.fffffffffffffp-1);
}

}  // namespace glint
