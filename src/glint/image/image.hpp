#pragma once

#include <cstddef>
#include <vector>

namespace glint {

// Linear RGB radiance, row-major from the top-left pixel, three floats per pixel.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;

    Image() = default;
    Image(int w, int h)
        : width(w), height(h), rgb(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3, 0.0f) {}
    float* pixel(int x, int y) { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
    const float* pixel(int x, int y) const { return &rgb[(static_cast<std::size_t>(y) * width + x) * 3]; }
};

}  // namespace glint
