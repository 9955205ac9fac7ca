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

// Sobol's first dimension as 32 bits of binary fraction: the van der Corput sequence Φ₂(i).
constexpr std::uint32_t sobol_dimension0(std::uint32_t i) {
    return reverse_bits(i);
}

// Sobol's second dimension (primitive polynomial x + 1: its generator matrix is Pascal's triangle
// mod 2), bit-reversed: bit t of the result is digit t + 1 of the binary fraction. Point i is the XOR of
// the direction numbers over the set bits j of i, and reversed direction number j is the polynomial
// (1 + x)^j over GF(2), so the whole sum is i's bit polynomial I(x) shifted to I(x + 1). That shift is
// five XOR-shifts, halving the problem each time because (x + 1)^(2^k) = x^(2^k) + 1 mod 2: no loop
// over the bits of i (which after the index scramble has all 32 of them).
constexpr std::uint32_t sobol_dimension1_reversed(std::uint32_t i) {
    i ^= (i >> 1) & 0x55555555u;
    i ^= (i >> 2) & 0x33333333u;
    i ^= (i >> 4) & 0x0f0f0f0fu;
    i ^= (i >> 8) & 0x00ff00ffu;
    i ^= i >> 16;
    return i;
}

// Sobol's second dimension as 32 bits of binary fraction. Together with dimension 0 the first 2^k
// points form a (0, k, 2)-net in base 2: exactly one point in each elementary interval of area 2^−k.
constexpr std::uint32_t sobol_dimension1(std::uint32_t i) {
    return reverse_bits(sobol_dimension1_reversed(i));
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

// Owen-scrambles a 32-bit binary fraction given bit-reversed (digit t + 1 in bit t, the form Sobol
// points are computed in): each digit is flipped or not by a hash of all the digits above it, so every
// elementary interval is kept whole and only shuffled among its siblings. Returns the fraction in
// natural order.
constexpr std::uint32_t owen_scramble_reversed(std::uint32_t reversed_bits, std::uint32_t seed) {
    return reverse_bits(laine_karras_permutation(reversed_bits, seed));
}

// Owen-scrambles a 32-bit binary fraction given in natural order.
constexpr std::uint32_t owen_scramble(std::uint32_t bits, std::uint32_t seed) {
    return owen_scramble_reversed(reverse_bits(bits), seed);
}

}  // namespace glint
