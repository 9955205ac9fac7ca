// Reading images from files, for textures and environment maps: one loader for every format glint
// reads, so that each user of images accepts the same files.
#include <stb_image.h>
#include <tinyexr.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "glint/image/image_io.hpp"

namespace glint {

double srgb_to_linear(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

namespace {

bool has_extension(const std::filesystem::path& path, const std::string& ext) {
    std::string e = path.extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
    return e == ext;
}

Image load_exr(const std::filesystem::path& path) {
    float* rgba = nullptr;
    int width = 0, height = 0;
    const char* error = nullptr;
    if (LoadEXR(&rgba, &width, &height, path.string().c_str(), &error) != TINYEXR_SUCCESS) {
        const std::string message = error ? error : "unknown error";
        FreeEXRErrorMessage(error);
        throw std::runtime_error(message);
    }
    Image image(width, height);
    for (size_t i = 0; i < static_cast<size_t>(width) * static_cast<size_t>(height); ++i) {
        for (size_t c = 0; c < 3; ++c) {
            image.rgb[3 * i + c] = rgba[4 * i + c];
        }
    }
    std::free(rgba);
    return image;
}

// stb_image, for every format it reads; `Sample` is the type of its pixels (byte, 16-bit or float).
template <typename Sample>
Image from_stb(Sample* pixels, int width, int height, double to_unit, bool srgb) {
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        throw std::runtime_error(reason ? reason : "unreadable image");
    }
    Image image(width, height);
    for (size_t i = 0; i < image.rgb.size(); ++i) {
        const double v = static_cast<double>(pixels[i]) * to_unit;
        image.rgb[i] = static_cast<float>(srgb ? srgb_to_linear(v) : v);
    }
    stbi_image_free(pixels);
    return image;
}

}  // namespace

Image read_image(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        throw std::runtime_error("no such file");
    }
    if (has_extension(path, ".exr")) {
        return load_exr(path);
    }
    if (has_extension(path, ".pfm")) {
        return read_pfm(path);
    }
    const std::string name = path.string();
    // Each loader fills width and height, so it must run before they are read (not as a sibling argument).
    int width = 0, height = 0, channels = 0;
    if (stbi_is_hdr(name.c_str())) {
        float* pixels = stbi_loadf(name.c_str(), &width, &height, &channels, 3);
        return from_stb(pixels, width, height, 1.0, false);
    }
    if (stbi_is_16_bit(name.c_str())) {
        stbi_us* pixels = stbi_load_16(name.c_str(), &width, &height, &channels, 3);
        return from_stb(pixels, width, height, 1.0 / 65535, true);
    }
    stbi_uc* pixels = stbi_load(name.c_str(), &width, &height, &channels, 3);
    return from_stb(pixels, width, height, 1.0 / 255, true);
}

}  // namespace glint
