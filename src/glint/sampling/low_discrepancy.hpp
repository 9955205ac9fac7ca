// The building blocks of the low-discrepancy patterns (Hammersley, Halton, Sobol): radical inverses,
// Sobol dimensions 0 to 3, and the scrambles that give every pixel its own randomised copy.
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

// Sobol's dimensions 2 and 3 (counting from 0), for the lens when it is stratified jointly with the film
// (SobolSampler): Joe & Kuo's direction numbers ("Constructing Sobol sequences with better
// two-dimensional projections", 2008, file new-joe-kuo-6.21201, their d = 3 and 4): primitive
// polynomials x² + x + 1 and x³ + x + 1, initial m = (1, 3) and (1, 3, 1). The recurrence is
// m_k = 2 a₁ m_(k−1) ⊕ … ⊕ 2^(s−1) a_(s−1) m_(k−s+1) ⊕ 2^s m_(k−s) ⊕ m_(k−s), and direction number k is
// the binary fraction m_k / 2^k.
struct SobolDirections {
    std::uint32_t degree;      // s
    std::uint32_t inner;       // a: the polynomial's inner coefficients a₁ … a_(s−1), a₁ highest
    std::uint32_t initial[4];  // m_1 … m_s
};
inline constexpr SobolDirections kSobolDimension2{2, 1, {1, 3}};
inline constexpr SobolDirections kSobolDimension3{3, 1, {1, 3, 1}};

// A Sobol dimension's point i for any 32-bit i, bit-reversed like sobol_dimension1_reversed: the XOR of
// the direction numbers over i's set bits, looked up a byte of i at a time (the index scramble leaves
// all 32 bits of i set, so a loop over them would be 32 steps).
class SobolReversedTable {
  public:
    constexpr explicit SobolReversedTable(const SobolDirections& d) {
        std::uint32_t m[33] = {};
        for (std::uint32_t k = 1; k <= 32; ++k) {
            if (k <= d.degree) {
                m[k] = d.initial[k - 1];
            } else {
                std::uint32_t next = m[k - d.degree] ^ (m[k - d.degree] << d.degree);
                for (std::uint32_t j = 1; j < d.degree; ++j) {
                    if ((d.inner >> (d.degree - 1 - j)) & 1u) {
                        next ^= m[k - j] << j;
                    }
                }
                m[k] = next;
            }
        }
        // Direction number k as 32 bits of fraction is m_k << (32 − k); the tables hold sums of them
        // bit-reversed (XOR commutes with the reversal), the form the scramble works on.
        std::uint32_t reversed[32] = {};
        for (std::uint32_t k = 1; k <= 32; ++k) {
            reversed[k - 1] = reverse_bits(m[k] << (32 - k));
        }
        for (std::uint32_t byte = 0; byte < 4; ++byte) {
            for (std::uint32_t value = 0; value < 256; ++value) {
                std::uint32_t sum = 0;
                for (std::uint32_t bit = 0; bit < 8; ++bit) {
                    if ((value >> bit) & 1u) {
                        sum ^= reversed[8 * byte + bit];
                    }
                }
                table_[byte][value] = sum;
            }
        }
    }
    constexpr std::uint32_t operator()(std::uint32_t i) const {
        return table_[0][i & 0xffu] ^ table_[1][(i >> 8) & 0xffu] ^ table_[2][(i >> 16) & 0xffu] ^
               table_[3][i >> 24];
    }
    // The table operator() reads byte `byte` of i in (256 entries): for a lookup in vector lanes.
    constexpr const std::uint32_t* byte_table(std::uint32_t byte) const { return table_[byte]; }

  private:
    std::uint32_t table_[4][256] = {};
};

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
