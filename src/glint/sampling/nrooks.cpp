#include "glint/sampling/nrooks.hpp"

#include <algorithm>

#include "glint/sampling/low_discrepancy.hpp"

namespace glint {

Point2 NRooksSampler::sample_2d(const SampleHashes& key, std::uint32_t dimension) const {
    const std::uint64_t pattern = key.pixel_bits(dimension);
    const std::uint32_t i = pattern_index(key, n_);
    // Sample i sits in column σ(i) and row τ(i); σ and τ are bijections, hence the n-rooks condition.
    const std::uint32_t column = permute(i, n_, static_cast<std::uint32_t>(pattern));
    const std::uint32_t row = permute(i, n_, static_cast<std::uint32_t>(pattern >> 32));
    const Point2 jitter = unit_pair(key.sample_bits(dimension));
    return {std::min((column + jitter.x) / n_, kOneMinusEpsilon),
            std::min((row + jitter.y) / n_, kOneMinusEpsilon)};
}

}  // namespace glint
