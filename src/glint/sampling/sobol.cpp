#include "glint/sampling/sobol.hpp"

#include <algorithm>
#include <cstring>

#include "glint/core/avx2_lanes.hpp"
#include "glint/core/cpu.hpp"
#include "glint/sampling/low_discrepancy.hpp"

#ifdef GLINT_HAVE_X86_SIMD
#include <immintrin.h>
#endif

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

#ifdef GLINT_HAVE_X86_SIMD
// ---- eight samples' camera points at a time, in the 32-bit lanes of AVX2 registers -------------------
// Each function is its scalar namesake (above, in low_discrepancy.hpp or in core/hash.hpp) lane by lane:
// integer operations that wrap as uint32_t does, and an exact conversion to double, so the same bits
// (SamplePatterns.CameraPointsTogetherAreOneByOnesPoints checks it).

GLINT_AVX2_INLINE __m256i broadcast(std::uint32_t x) {
    return _mm256_set1_epi32(static_cast<int>(x));
}

// reverse_bits: the bytes of each lane in reverse order, then the bits of each byte, a nibble at a time
// by table.
GLINT_AVX2_INLINE __m256i reverse_bits_lanes(__m256i x) {
    const __m256i byte_order = _mm256_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12, 3, 2, 1,
                                                0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12);
    const __m256i nibble_reversed =
        _mm256_setr_epi8(0x0, 0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf, 0x0,
                         0x8, 0x4, 0xc, 0x2, 0xa, 0x6, 0xe, 0x1, 0x9, 0x5, 0xd, 0x3, 0xb, 0x7, 0xf);
    const __m256i low_nibbles = _mm256_set1_epi8(0x0f);
    x = _mm256_shuffle_epi8(x, byte_order);
    const __m256i low = _mm256_and_si256(x, low_nibbles);
    const __m256i high = _mm256_and_si256(_mm256_srli_epi16(x, 4), low_nibbles);
    // A byte's low nibble reversed becomes its high one (each byte is below 16 before the shift, so no
    // bit crosses into the next byte).
    return _mm256_or_si256(_mm256_slli_epi16(_mm256_shuffle_epi8(nibble_reversed, low), 4),
                           _mm256_shuffle_epi8(nibble_reversed, high));
}

GLINT_AVX2_INLINE __m256i laine_karras_lanes(__m256i x, __m256i seed) {
    x = _mm256_add_epi32(x, seed);
    x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, broadcast(0x6c50b47cu)));
    x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, broadcast(0xb82f1e52u)));
    x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, broadcast(0xc7afe638u)));
    x = _mm256_xor_si256(x, _mm256_mullo_epi32(x, broadcast(0x8d22f6e6u)));
    return x;
}

GLINT_AVX2_INLINE __m256i xor_shifted_masked(__m256i i, int shift, std::uint32_t mask) {
    return _mm256_xor_si256(i, _mm256_and_si256(_mm256_srli_epi32(i, shift), broadcast(mask)));
}

GLINT_AVX2_INLINE __m256i sobol_dimension1_reversed_lanes(__m256i i) {
    i = xor_shifted_masked(i, 1, 0x55555555u);
    i = xor_shifted_masked(i, 2, 0x33333333u);
    i = xor_shifted_masked(i, 4, 0x0f0f0f0fu);
    i = xor_shifted_masked(i, 8, 0x00ff00ffu);
    return _mm256_xor_si256(i, _mm256_srli_epi32(i, 16));
}

GLINT_AVX2_INLINE __m256i table_lanes(const SobolReversedTable& table, __m256i i) {
    const __m256i byte = broadcast(0xffu);
    __m256i sum = _mm256_setzero_si256();
    for (std::uint32_t b = 0; b < 4; ++b) {
        const __m256i index = _mm256_and_si256(_mm256_srli_epi32(i, static_cast<int>(8 * b)), byte);
        sum = _mm256_xor_si256(
            sum, _mm256_i32gather_epi32(reinterpret_cast<const int*>(table.byte_table(b)), index, 4));
    }
    return sum;
}

// scrambled_index: the samples' reversed indices Owen-scrambled by a dimension's seed, in natural order.
GLINT_AVX2_INLINE __m256i scrambled_index_lanes(__m256i sample_reversed, __m256i seed) {
    return reverse_bits_lanes(laine_karras_lanes(sample_reversed, seed));
}

// bits_to_unit of lanes 0–3 and of lanes 4–7: the unsigned lanes made signed by flipping their top bit
// (x − 2^31), converted, then 2^31 added back; every step is exact.
GLINT_AVX2_INLINE void to_unit_lanes(__m256i bits, __m256d& lanes_0_3, __m256d& lanes_4_7) {
    const __m256i flipped = _mm256_xor_si256(bits, broadcast(0x80000000u));
    const __m256d half_range = _mm256_set1_pd(0x1p31);
    const __m256d scale = _mm256_set1_pd(0x1p-32);
    lanes_0_3 =
        _mm256_mul_pd(_mm256_add_pd(_mm256_cvtepi32_pd(_mm256_castsi256_si128(flipped)), half_range), scale);
    lanes_4_7 = _mm256_mul_pd(
        _mm256_add_pd(_mm256_cvtepi32_pd(_mm256_extracti128_si256(flipped, 1)), half_range), scale);
}

// scrambled_point of eight reversed points sharing their scramble seeds (one pixel's, one dimension's):
// x in natural order as doubles in `x_0_3`, `x_4_7`, y likewise.
struct PointLanes {
    __m256d x_0_3, x_4_7, y_0_3, y_4_7;
};
GLINT_AVX2_INLINE PointLanes scrambled_point_lanes(__m256i x_reversed, __m256i y_reversed,
                                                   std::uint64_t scramble_seeds) {
    const __m256i x = reverse_bits_lanes(
        laine_karras_lanes(x_reversed, broadcast(static_cast<std::uint32_t>(scramble_seeds))));
    const __m256i y = reverse_bits_lanes(
        laine_karras_lanes(y_reversed, broadcast(static_cast<std::uint32_t>(scramble_seeds >> 32))));
    PointLanes p;
    to_unit_lanes(x, p.x_0_3, p.x_4_7);
    to_unit_lanes(y, p.y_0_3, p.y_4_7);
    return p;
}

// Four samples' (film x, film y, lens x, lens y) as four (x, y, x, y) rows: a 4 × 4 transpose.
GLINT_AVX2_INLINE void store_rows(__m256d film_x, __m256d film_y, __m256d lens_x, __m256d lens_y,
                                  FilmAndLens* out, std::uint32_t count) {
    const __m256d film_even = _mm256_unpacklo_pd(film_x, film_y);  // samples 0 and 2
    const __m256d film_odd = _mm256_unpackhi_pd(film_x, film_y);   // samples 1 and 3
    const __m256d lens_even = _mm256_unpacklo_pd(lens_x, lens_y);
    const __m256d lens_odd = _mm256_unpackhi_pd(lens_x, lens_y);
    const __m256d rows[4] = {
        _mm256_permute2f128_pd(film_even, lens_even, 0x20), _mm256_permute2f128_pd(film_odd, lens_odd, 0x20),
        _mm256_permute2f128_pd(film_even, lens_even, 0x31), _mm256_permute2f128_pd(film_odd, lens_odd, 0x31)};
    static_assert(sizeof(FilmAndLens) == sizeof(__m256d));
    for (std::uint32_t i = 0; i < count; ++i) {
        std::memcpy(static_cast<void*>(out + i), &rows[i], sizeof(FilmAndLens));
    }
}

__attribute__((target("avx2,fma"))) void camera_points_avx2(const PixelHashes& pixel, std::uint32_t first,
                                                            bool lens, std::span<FilmAndLens> out) {
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i film_seed = broadcast(static_cast<std::uint32_t>(pixel.bits[kFilmDimension]));
    for (std::size_t done = 0; done < out.size(); done += 8) {
        const auto count = static_cast<std::uint32_t>(std::min<std::size_t>(8, out.size() - done));
        // Lanes past `count` compute points no one reads.
        const __m256i sample = _mm256_add_epi32(broadcast(first + static_cast<std::uint32_t>(done)), lane);
        // reversed_point(key, kFilmDimension): the film's scrambled index is its point's reversed x.
        const __m256i index = scrambled_index_lanes(reverse_bits_lanes(sample), film_seed);
        const PointLanes film = scrambled_point_lanes(index, sobol_dimension1_reversed_lanes(index),
                                                      pixel.mixed_bits[kFilmDimension]);
        PointLanes lens_lanes{};  // {0, 0} points without a lens, as one sample at a time gives
        if (lens) {
            lens_lanes = scrambled_point_lanes(table_lanes(kSobolDimension2Reversed, index),
                                               table_lanes(kSobolDimension3Reversed, index),
                                               pixel.mixed_bits[kLensDimension]);
        }
        FilmAndLens* rows = out.data() + done;
        store_rows(film.x_0_3, film.y_0_3, lens_lanes.x_0_3, lens_lanes.y_0_3, rows, std::min(count, 4u));
        if (count > 4) {
            store_rows(film.x_4_7, film.y_4_7, lens_lanes.x_4_7, lens_lanes.y_4_7, rows + 4, count - 4);
        }
    }
}

// Four samples' points of one dimension, (x, y) pairs from x and y lanes, into `out`'s entries i … i + 3
// (as many as `count`).
GLINT_AVX2_INLINE void store_pairs(__m256d x, __m256d y, std::uint32_t dimension, IntegratorPoints* out,
                                   std::uint32_t count) {
    const __m256d even = _mm256_unpacklo_pd(x, y);  // samples 0 and 2
    const __m256d odd = _mm256_unpackhi_pd(x, y);   // samples 1 and 3
    const __m128d pairs[4] = {_mm256_castpd256_pd128(even), _mm256_castpd256_pd128(odd),
                              _mm256_extractf128_pd(even, 1), _mm256_extractf128_pd(odd, 1)};
    static_assert(sizeof(Point2) == sizeof(__m128d));
    for (std::uint32_t i = 0; i < count; ++i) {
        std::memcpy(static_cast<void*>(&out[i].point[dimension]), &pairs[i], sizeof(Point2));
    }
}

__attribute__((target("avx2,fma"))) void integrator_points_avx2(const PixelHashes& pixel, std::uint32_t first,
                                                                std::span<IntegratorPoints> out) {
    static_assert(kFirstIntegratorDimension + kBatchedDimensions <= SobolSampler::kStratifiedDimensions);
    const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    for (std::size_t done = 0; done < out.size(); done += 8) {
        const auto count = static_cast<std::uint32_t>(std::min<std::size_t>(8, out.size() - done));
        // Lanes past `count` compute points no one reads.
        const __m256i sample_reversed =
            reverse_bits_lanes(_mm256_add_epi32(broadcast(first + static_cast<std::uint32_t>(done)), lane));
        IntegratorPoints* rows = out.data() + done;
        for (std::uint32_t i = 0; i < kBatchedDimensions; ++i) {
            const std::uint32_t dimension = kFirstIntegratorDimension + i;
            // reversed_point(key, dimension): the index scrambled by the dimension's own seed, then
            // Sobol's dimensions 0 (the index itself, reversed) and 1 of it.
            const __m256i index = scrambled_index_lanes(
                sample_reversed, broadcast(static_cast<std::uint32_t>(pixel.bits[dimension])));
            const PointLanes point = scrambled_point_lanes(index, sobol_dimension1_reversed_lanes(index),
                                                           pixel.mixed_bits[dimension]);
            store_pairs(point.x_0_3, point.y_0_3, i, rows, std::min(count, 4u));
            if (count > 4) {
                store_pairs(point.x_4_7, point.y_4_7, i, rows + 4, count - 4);
            }
        }
    }
}
#endif

}  // namespace

Point2 SobolSampler::sample_2d(const SampleHashes& key, std::uint32_t dimension) const {
    if (dimension >= kStratifiedDimensions) {
        return random_point(key, dimension);
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
        return random_point(key, dimension).x;
    }
    const ReversedPoint point = reversed_point(key, dimension);
    return bits_to_unit(owen_scramble_reversed(point.x, static_cast<std::uint32_t>(point.scramble_seeds)));
}

void SobolSampler::camera_points(const PixelHashes& pixel, std::uint32_t first, bool lens,
                                 std::span<FilmAndLens> out) const {
#ifdef GLINT_HAVE_X86_SIMD
    if (cpu_has_avx2_and_fma()) {
        camera_points_avx2(pixel, first, lens, out);
        return;
    }
#endif
    Sampler::camera_points(pixel, first, lens, out);
}

bool SobolSampler::integrator_points(const PixelHashes& pixel, std::uint32_t first,
                                     std::span<IntegratorPoints> out) const {
#ifdef GLINT_HAVE_X86_SIMD
    if (cpu_has_avx2_and_fma()) {
        integrator_points_avx2(pixel, first, out);
        return true;
    }
#endif
    // One sample at a time would cost what the stream's own calls cost, and some dimensions go unread.
    return Sampler::integrator_points(pixel, first, out);
}

}  // namespace glint
