#include "glint/sampling/halton.hpp"

#include <algorithm>
#include <array>

#include "glint/sampling/low_discrepancy.hpp"

namespace glint {

namespace {

// 3^20 < 2^32 < 3^21: 21 base-3 digits hold every 32-bit index.
constexpr std::uint32_t kMaxDigits3 = 21;

// The number of base-3 digits of the indices 0 … n−1 (at least 1).
std::uint32_t digits3_of_count(std::uint32_t n) {
    std::uint32_t digits = 1;
    for (std::uint64_t power = 3; power < n && digits < kMaxDigits3; power *= 3) {
        ++digits;
    }
    return digits;
}

}  // namespace

double owen_scrambled_radical_inverse3(std::uint32_t i, std::uint64_t seed, std::uint32_t scrambled_digits) {
    // The six permutations of the digits {0, 1, 2}.
    static constexpr std::array<std::array<std::uint8_t, 3>, 6> kPermutations = {
        {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
    double result = 0;
    double weight = 1.0 / 3.0;
    std::uint64_t prefix = 1;  // the original digits seen so far, with a leading 1
    for (std::uint32_t j = 0; j < std::min(scrambled_digits, kMaxDigits3); ++j) {
        const std::uint32_t digit = i % 3;
        i /= 3;
        // One SplitMix64 output per distinct prefix; its top bits pick one of six permutations by a
        // multiply instead of a modulo.
        const std::uint64_t bits = mix64(seed + prefix * kGoldenGamma);
        const auto& permutation = kPermutations[((bits >> 32) * 6) >> 32];
        result += permutation[digit] * weight;
        weight *= 1.0 / 3.0;
        prefix = prefix * 3 + digit;
    }
    // The lower digits, all permuted independently at random, place the point uniformly inside the
    // finest stratum reached: one uniform number of the full prefix stands for all of them.
    result += to_unit_double(mix64(seed ^ prefix * 0xd1342543de82ef95ull)) * (3 * weight);
    return std::min(result, kOneMinusEpsilon);
}

HaltonSampler::HaltonSampler(std::uint32_t samples_per_pixel)
    : n_(std::max(1u, samples_per_pixel)), digits3_(digits3_of_count(n_)) {}

Point2 HaltonSampler::sample_2d(const SampleHashes& key, std::uint32_t dimension) const {
    const std::uint64_t pattern = key.pixel_bits(dimension);
    const std::uint32_t i = permute(pattern_index(key, n_), n_, static_cast<std::uint32_t>(pattern));
    const double x = bits_to_unit(owen_scramble(reverse_bits(i), static_cast<std::uint32_t>(pattern >> 32)));
    const double y = owen_scrambled_radical_inverse3(i, key.pixel_bits_mixed(dimension), digits3_);
    return {x, y};
}

}  // namespace glint
