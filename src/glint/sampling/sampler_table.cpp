// The one name → constructor table of sample patterns. Adding a pattern: a file in this folder and a
// line here.
#include "glint/sampling/jittered.hpp"
#include "glint/sampling/random.hpp"

namespace glint {

const std::vector<SamplerEntry>& sampler_table() {
    static const std::vector<SamplerEntry> table = {
        {"random", "independent uniform points (paper §2.2)",
         [](std::uint32_t n) { return std::make_unique<RandomSampler>(n); }},
        {"jittered", "one random point per cell of a k×k grid; n rounded up to a square (paper §2.3)",
         [](std::uint32_t n) { return std::make_unique<JitteredSampler>(n); }},
    };
    return table;
}

std::unique_ptr<Sampler> make_sampler(const std::string& name, std::uint32_t samples_per_pixel) {
    for (const SamplerEntry& entry : sampler_table()) {
        if (entry.name == name) {
            return entry.create(samples_per_pixel);
        }
    }
    return nullptr;
}

std::vector<std::string> sampler_names() {
    std::vector<std::string> names;
    for (const SamplerEntry& entry : sampler_table()) {
        names.push_back(entry.name);
    }
    return names;
}

}  // namespace glint
