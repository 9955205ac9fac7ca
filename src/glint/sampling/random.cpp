// Random sampling (paper §2.2): every point independent and uniform. Aliasing becomes noise, but
// points clump and leave gaps; the reference every other pattern is measured against.
#include "glint/sampling/random.hpp"

namespace glint {

Point2 RandomSampler::sample_2d(const SampleHashes& key, std::uint32_t dimension) const {
    return random_point(key, dimension);
}

}  // namespace glint
