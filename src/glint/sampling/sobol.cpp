#include "glint/sampling/sobol.hpp"

#include "glint/sampling/low_discrepancy.hpp"

namespace glint {

namespace {

// The sample's index in the pixel's aligned block of 2^32 Sobol points, Owen-scrambled by the low half
// of `seeds` (owen_scramble(key.sample(), …), from the reversed index the key keeps).
std::uint32_t scrambled_index(const SampleHashes& key, std::uint64_t seeds) {
    return owen_scramble_reversed(key.sample_reversed(), static_cast<std::uint32_t>(seeds));
}

}  // namespace

Point2 SobolSampler::sample_2d(const SampleHashes& key, std::uint32_t dimension) const {
    if (dimension >= kStratifiedDimensions) {
        return unit_pair(key.sample_bits(dimension));  // the random pattern's point
    }
    const std::uint64_t seeds = key.pixel_bits(dimension);
    const std::uint32_t index = scrambled_index(key, seeds);
    // The point's two seeds, drawn while the index is scrambled.
    const std::uint64_t point_seeds = mix64(seeds);
    // Both dimensions are computed bit-reversed (dimension 0 reversed is the index itself) and
    // scrambled (owen_scramble_reversed without its final reversal), then put back in natural order
    // together by one 64-bit reversal, which swaps the halves: x, packed low, comes out high.
    const std::uint32_t x_reversed = laine_karras_permutation(index, static_cast<std::uint32_t>(point_seeds));
    const std::uint32_t y_reversed = laine_karras_permutation(sobol_dimension1_reversed(index),
                                                              static_cast<std::uint32_t>(point_seeds >> 32));
    const std::uint64_t natural = reverse_bits64(std::uint64_t{y_reversed} << 32 | x_reversed);
    return {bits_to_unit(static_cast<std::uint32_t>(natural >> 32)),
            bits_to_unit(static_cast<std::uint32_t>(natural))};
}

double SobolSampler::sample_1d(const SampleHashes& key, std::uint32_t dimension) const {
    // sample_2d's x without its y: the point's first dimension, stratified in n intervals.
    if (dimension >= kStratifiedDimensions) {
        return unit_pair(key.sample_bits(dimension)).x;
    }
    const std::uint64_t seeds = key.pixel_bits(dimension);
    const std::uint32_t index = scrambled_index(key, seeds);
    return bits_to_unit(owen_scramble_reversed(index, static_cast<std::uint32_t>(mix64(seeds))));
}

}  // namespace glint
