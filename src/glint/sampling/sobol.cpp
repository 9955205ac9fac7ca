#include "glint/sampling/sobol.hpp"

#include "glint/sampling/low_discrepancy.hpp"

namespace glint {

namespace {

// The sample's index in the pixel's aligned block of 2^32 Sobol points, Owen-scrambled by the low half
// of `seeds` (owen_scramble(key.sample(), …), from the reversed index the key keeps).
std::uint32_t scrambled_index(const SampleHashes& key, std::uint64_t seeds) {
    return owen_scramble_reversed(key.sample_reversed(), static_cast<std::uint32_t>(seeds));
}

// Sobol's dimensions 2 and 3, for the lens.
constexpr SobolReversedTable kSobolDimension2Reversed{kSobolDimension2};
constexpr SobolReversedTable kSobolDimension3Reversed{kSobolDimension3};

// A stratified 2-D dimension's Sobol point, bit-reversed and not yet Owen-scrambled, with the two seeds
// that scramble it.
struct ReversedPoint {
    std::uint32_t x, y;
    std::uint64_t scramble_seeds;
};

// The lens's point, from the film's scrambled index: Sobol's dimensions 2 and 3 of it, so that film and
// lens together are the first four dimensions of one Sobol point, stratified jointly rather than paired
// at random. A defocused pixel's colour depends on where the film and lens points fall together (the
// ray they make), so joint strata pay: RTIOW's final scene at 32 spp has 4.3 % less error
// (bench/quality.py).
__attribute__((always_inline)) inline ReversedPoint lens_point(std::uint32_t film_index,
                                                               std::uint64_t scramble_seeds) {
    return {kSobolDimension2Reversed(film_index), kSobolDimension3Reversed(film_index), scramble_seeds};
}

// Inlined: a call of its own made the Cornell box run 0.7 % more instructions.
__attribute__((always_inline)) inline ReversedPoint reversed_point(const SampleHashes& key,
                                                                   std::uint32_t dimension) {
    const std::uint64_t seeds = key.pixel_bits(dimension);
    // The point's two seeds, drawn while the index is scrambled.
    const std::uint64_t scramble_seeds = key.pixel_bits_mixed(dimension);
    if (dimension == kLensDimension) {
        return lens_point(scrambled_index(key, key.pixel_bits(kFilmDimension)), scramble_seeds);
    }
    // Dimension 0 reversed is the index itself.
    const std::uint32_t index = scrambled_index(key, seeds);
    return {index, sobol_dimension1_reversed(index), scramble_seeds};
}

// Both coordinates are scrambled bit-reversed (owen_scramble_reversed without its final reversal), then
// put back in natural order together by one 64-bit reversal, which swaps the halves: x, packed low,
// comes out high.
__attribute__((always_inline)) inline Point2 scrambled_point(const ReversedPoint& point) {
    const std::uint32_t x_reversed =
        laine_karras_permutation(point.x, static_cast<std::uint32_t>(point.scramble_seeds));
    const std::uint32_t y_reversed =
        laine_karras_permutation(point.y, static_cast<std::uint32_t>(point.scramble_seeds >> 32));
    const std::uint64_t natural = reverse_bits64(std::uint64_t{y_reversed} << 32 | x_reversed);
    return {bits_to_unit(static_cast<std::uint32_t>(natural >> 32)),
            bits_to_unit(static_cast<std::uint32_t>(natural))};
}

}  // namespace

Point2 SobolSampler::sample_2d(const SampleHashes& key, std::uint32_t dimension) const {
    if (dimension >= kStratifiedDimensions) {
        return unit_pair(key.sample_bits(dimension));  // the random pattern's point
    }
    return scrambled_point(reversed_point(key, dimension));
}

FilmAndLens SobolSampler::sample_film_and_lens(const SampleHashes& key) const {
    static_assert(kFilmDimension < kStratifiedDimensions && kLensDimension < kStratifiedDimensions);
    const ReversedPoint film = reversed_point(key, kFilmDimension);
    // film.x is the film's scrambled index (dimension 0 reversed is the index itself); the lens's seeds
    // are reversed_point's for its dimension (SamplePatterns.FilmAndLensInOneCallAreTheirDimensionsPoints
    // checks that the two ways agree).
    return {scrambled_point(film), scrambled_point(lens_point(film.x, key.pixel_bits_mixed(kLensDimension)))};
}

double SobolSampler::sample_1d(const SampleHashes& key, std::uint32_t dimension) const {
    // sample_2d's x without its y.
    if (dimension >= kStratifiedDimensions) {
        return unit_pair(key.sample_bits(dimension)).x;
    }
    const ReversedPoint point = reversed_point(key, dimension);
    return bits_to_unit(owen_scramble_reversed(point.x, static_cast<std::uint32_t>(point.scramble_seeds)));
}

}  // namespace glint
