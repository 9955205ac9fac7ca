#include "glint/sampling/halton.hpp"

#include <algorithm>
#include <array>

#include "glint/sampling/low_discrepancy.hpp"

namespace glint {

double owen_scrambled_radical_inverse3(std::uint32_t i, std::uint64_t seed) {
    // The six permutations of the digits {0, 1, 2}.
    static constexpr std::array<std::array<std::uint8_t, 3>, 6> kPermutations = {
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    // 3^21 > 2^32: 21 digits hold every 32-bit index. The zero digits above the index are permuted too
    // (their scrambled values are what places the point inside its finest stratum).
    constexpr int kDigits = 21;
    double result = 0;
    double weight = 1.0 / 3.0;
    std::uint64_t prefix = 1;  // the original digits seen so far, with a leading 1
    for (int j = 0; j < kDigits; ++j) {
        const std::uint32_t digit = i % 3;
        i /= 3;
        const auto& permutation = kPermutations[hash_values(seed, prefix) % 6];
        result += permutation[digit] * weight;
        weight *= 1.0 / 3.0;
        prefix = prefix * 3 + digit;
    }
    return std::min(result, kOneMinusEpsilon);
}

Point2 HaltonSampler::sample_2d(const SampleKey& key, std::uint32_t dimension) const {
    const std::uint64_t pattern = pattern_key(key, dimension, 0x4a17u);
    const std::uint32_t i = permute(key.sample % n_, n_, static_cast<std::uint32_t>(pattern));
    const double x = bits_to_unit(owen_scramble(reverse_bits(i), static_cast<std::uint32_t>(pattern >> 32)));
    const double y = owen_scrambled_radical_inverse3(i, hash_values(pattern, 3));
    return {x, y};
}

}  // namespace glint
