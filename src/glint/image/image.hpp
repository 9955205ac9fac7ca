#pragma once

#include <cstddef>
#include <string>
#include <utility>
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

// An image of any number of named channels (an AOV: albedo R, G, B; depth Z), interleaved per pixel,
// written as a layer of a multi-layer EXR or as a file of its own.
struct ImageLayer {
    std::string name;                   // "albedo": its channels are written as "albedo.R", …
    std::vector<std::string> channels;  // "R", "G", "B"; or one, "Z"
    int width = 0;
    int height = 0;
    std::vector<float> values;  // width × height × channels.size(), row by row

    ImageLayer(std::string name_, std::vector<std::string> channels_, int w, int h)
        : name(std::move(name_)),
          channels(std::move(channels_)),
          width(w),
          height(h),
          values(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * channels.size(), 0.0f) {}
    float* pixel(int x, int y) {
        return &values[(static_cast<std::size_t>(y) * width + x) * channels.size()];
    }
    const float* pixel(int x, int y) const {
        return &values[(static_cast<std::size_t>(y) * width + x) * channels.size()];
    }
};

}  // namespace glint
