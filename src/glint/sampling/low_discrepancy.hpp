// The building blocks of the low-discrepancy patterns (Hammersley, Halton, Sobol): radical inverses,
// the first two Sobol dimensions, and the scrambles that give every pixel its own randomised copy.
#pragma once

#include <cstdint>

#include "glint/core/hash.hpp"

namespace glint {

// The largest double below 1: patterns clamp to it so that no point ever reaches 1.
inline constexpr double kOneMinusEpsilon = 0x1.fffffffffffffp-1;

// Φ_b(i): the digits a_j of i in base b mirrored about the radix point, Σ a_j b^(−j−1) (paper §3.3,
// eq. 2 as corrected by the errata: the sum runs over the digits of i). Φ₂(5) = 0.101₂ = 0.625.
constexpr double radical_inverse(std::uint32_t base, std::uint64_t i) {
    const double inv_base = 1.0 / base;
    double inv_power = inv_base;
    double result = 0;
    while (i > 0) {
        result += static_cast<double>(i % base) * inv_power;
        i /= base;
        inv_power *= inv_base;
    }
    return result;
}

constexpr std::uint32_t reverse_bits(std::uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

// Sobol's first dimension as 32 bits of binary fraction: the van der Corput sequence Φ₂(i).
constexpr std::uint32_t sobol_dimension0(std::uint32_t i) {
    return reverse_bits(i);
}

// Sobol's second dimension (primitive polynomial x + 1: its generator matrix is Pascal's triangle
// mod 2), as 32 bits of binary fraction. Together with dimension 0 the first 2^k points form a
// (0, k, 2)-net in base 2: exactly one point in each elementary interval of area 2^−k.
constexpr std::uint32_t sobol_dimension1(std::uint32_t i) {
    std::uint32_t result = 0;
    for (std::uint32_t v = 1u << 31; i != 0; i >>= 1, v ^= v >> 1) {
        if (i & 1u) {
            result ^= v;
        }
    }
    return result;
}

// Laine & Karras' hash ("Stratified sampling for stochastic transparency", 2011) in Burley's improved
// form ("Practical Hash-based Owen Scrambling", JCGT 2020). Bit j of the result depends only on bits
// 0 … j of x, so on bit-reversed values it is a nested uniform (Owen) scramble.
constexpr std::uint32_t laine_karras_permutation(std::uint32_t x, std::uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// Owen-scrambles a 32-bit binary fraction: each digit is flipped or not by a hash of all the digits
// above it, so every elementary interval is kept whole and only shuffled among its siblings.
constexpr std::uint32_t owen_scramble(std::uint32_t bits, std::uint32_t seed) {
    return reverse_bits(laine_karras_permutation(reverse_bits(bits), seed));
}

// A 32-bit binary fraction as a double in [0, 1).
constexpr double bits_to_unit(std::uint32_t bits) {
    return static_cast<double>(bits) * 0x1.0p-32;
}

// The per-pixel, per-dimension scramble key of a pattern: neighbouring pixels (and the film and lens
// dimensions of one pixel) get unrelated keys. `pattern_tag` keeps different patterns apart.
inline std::uint64_t pattern_key(const SampleKey& key, std::uint32_t dimension, std::uint32_t pattern_tag) {
    return hash_values(key.seed, key.pixel_x, key.pixel_y, dimension, pattern_tag);
}

}  // namespace glint
