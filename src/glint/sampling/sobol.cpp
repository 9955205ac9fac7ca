#include "glint/sampling/sobol.hpp"

#include "glint/sampling/low_discrepancy.hpp"

namespace glint {

Point2 SobolSampler::sample_2d(const SampleKey& key, std::uint32_t dimension) const {
    const std::uint64_t pattern = pattern_key(key, dimension, 0x5011u);
    const std::uint64_t seeds = hash_values(pattern, 1);
    const std::uint32_t index = owen_scramble(key.sample, static_cast<std::uint32_t>(pattern));
    const std::uint32_t x = owen_scramble(sobol_dimension0(index), static_cast<std::uint32_t>(seeds));
    const std::uint32_t y = owen_scramble(sobol_dimension1(index), static_cast<std::uint32_t>(seeds >> 32));
    return {bits_to_unit(x), bits_to_unit(y)};
}

}  // namespace glint
