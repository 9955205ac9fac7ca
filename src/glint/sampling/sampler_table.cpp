// The one name → constructor table of sample patterns. Adding a pattern: a file in this folder and a
// line here.
#include "glint/sampling/halton.hpp"
#include "glint/sampling/hammersley.hpp"
#include "glint/sampling/jittered.hpp"
#include "glint/sampling/multijittered.hpp"
#include "glint/sampling/nrooks.hpp"
#include "glint/sampling/random.hpp"
#include "glint/sampling/regular.hpp"
#include "glint/sampling/sobol.hpp"

namespace glint {

const NameTable<SamplerEntry>& sampler_table() {
    static const NameTable<SamplerEntry> table = {
        {"regular",
         "the centres of a k×k grid, the same in every pixel; n rounded up to a square (paper §2.1)",
         [](std::uint32_t n) { return std::make_unique<RegularSampler>(n); }},
        {"random", "independent uniform points (paper §2.2)",
         [](std::uint32_t n) { return std::make_unique<RandomSampler>(n); }},
        {"jittered", "one random point per cell of a k×k grid; n rounded up to a square (paper §2.3)",
         [](std::uint32_t n) { return std::make_unique<JitteredSampler>(n); }},
        {"n-rooks", "one point per row and per column of the n×n grid; any n (paper §3.1)",
         [](std::uint32_t n) { return std::make_unique<NRooksSampler>(n); }},
        {"multi-jittered",
         "n-rooks on the n×n grid and jittered on the coarse m×(n/m) grid, Kensler's correlated form (paper "
         "§3.2)",
         [](std::uint32_t n) { return std::make_unique<MultiJitteredSampler>(n); }},
        {"hammersley", "(i/n, Φ₂(i)), rotated in x and digit-scrambled in y per pixel (paper §3.3)",
         [](std::uint32_t n) { return std::make_unique<HammersleySampler>(n); }},
        {"halton", "(Φ₂(i), Φ₃(i)), Owen-scrambled per pixel",
         [](std::uint32_t n) { return std::make_unique<HaltonSampler>(n); }},
        {"sobol",
         "Sobol points, Owen-scrambled per pixel (Burley 2020); film and lens one 4-D point; random past the "
         "sixth",
         [](std::uint32_t n) { return std::make_unique<SobolSampler>(n); }},
    };
    return table;
}

std::unique_ptr<Sampler> make_sampler(const std::string& name, std::uint32_t samples_per_pixel) {
    const SamplerEntry* entry = sampler_table().find(name);
    return entry ? entry->create(samples_per_pixel) : nullptr;
}

}  // namespace glint
