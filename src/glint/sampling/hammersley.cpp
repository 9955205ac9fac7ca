#include "glint/sampling/hammersley.hpp"

#include <algorithm>

#include "glint/sampling/low_discrepancy.hpp"

namespace glint {

Point2 hammersley_point(std::uint32_t i, std::uint32_t n) {
    return {static_cast<double>(i) / n, radical_inverse(2, i)};
}

Point2 HammersleySampler::sample_2d(const SampleHashes& key, std::uint32_t dimension) const {
    const std::uint64_t pattern = key.pixel_bits(dimension);
    const std::uint32_t i = permute(pattern_index(key, n_), n_, static_cast<std::uint32_t>(pattern));
    // The rotation (high half) and the offset (low half) of x, the same for every point of the pixel.
    const std::uint64_t rotation = key.pixel_bits_mixed(dimension);
    const std::uint32_t stratum = static_cast<std::uint32_t>((i + (rotation >> 32) % n_) % n_);
    const double offset = bits_to_unit(static_cast<std::uint32_t>(rotation));
    const double x = std::min((stratum + offset) / n_, kOneMinusEpsilon);
    // reverse_bits(i) is Φ₂(i) as a 32-bit binary fraction; the XOR flips the same digits for all i.
    const double y = bits_to_unit(reverse_bits(i) ^ static_cast<std::uint32_t>(pattern >> 32));
    return {x, y};
}

}  // namespace glint
