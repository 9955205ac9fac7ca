#pragma once

#include <cstdint>
#include <string>

namespace glint {

// How to render: the scene's `render:` block with the command line's overrides applied.
struct RenderSettings {
    int width = 640;
    int height = 360;
    std::uint32_t samples_per_pixel = 16;  // requested; the sampler may round it (jittered: to a square)
    std::string sampler = "jittered";
    std::string integrator = "raycast";
    std::string accelerator = "bvh";
    int max_depth = 5;
    std::uint64_t seed = 1;
    int threads = 0;     // 0: all cores
    int tile_size = 16;  // pixels per tile side; the image does not depend on it
};

}  // namespace glint
