#include "glint/sampling/nrooks.hpp"

#include <algorithm>

#include "glint/sampling/low_discrepancy.hpp"

namespace glint {

Point2 NRooksSampler::sample_2d(const SampleKey& key, std::uint32_t dimension) const {
    const std::uint64_t pattern = pattern_key(key, dimension, 0x2007u);
    const std::uint32_t i = key.sample % n_;
    // Sample i sits in column σ(i) and row τ(i); σ and τ are bijections, hence the n-rooks condition.
    const std::uint32_t column = permute(i, n_, static_cast<std::uint32_t>(pattern));
    const std::uint32_t row = permute(i, n_, static_cast<std::uint32_t>(pattern >> 32));
    const double jx = key.uniform(2 * dimension);
    const double jy = key.uniform(2 * dimension + 1);
    return {std::min((column + jx) / n_, kOneMinusEpsilon), std::min((row + jy) / n_, kOneMinusEpsilon)};
}

}  // namespace glint
