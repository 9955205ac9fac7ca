// Image {type: image, file: x.png}: `file` resolves against the scene file's folder. 8- and 16-bit files
// are sRGB-decoded; HDR and EXR are taken as linear. A missing or unreadable file is an error at `file`.
#include "glint/texture/image_texture.hpp"

#include <stb_image.h>
#include <tinyexr.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "glint/scene/build_context.hpp"
#include "glint/scene/params.hpp"

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

Image load_texture_image(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        throw std::runtime_error("no such file");
    }
    if (has_extension(path, ".exr")) {
        return load_exr(path);
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

ImageTexture::ImageTexture(Image image) : image_(std::move(image)) {
    if (image_.width <= 0 || image_.height <= 0) {
        throw std::invalid_argument("an image texture needs at least one pixel");
    }
    const auto [lo, hi] = std::minmax_element(image_.rgb.begin(), image_.rgb.end());
    min_ = *lo;
    max_ = *hi;
}

Rgb ImageTexture::texel(long long x, long long y) const {
    const auto wrap = [](long long i, long long n) { return ((i % n) + n) % n; };
    const float* p =
        image_.pixel(static_cast<int>(wrap(x, image_.width)), static_cast<int>(wrap(y, image_.height)));
    return {p[0], p[1], p[2]};
}

Rgb ImageTexture::lookup(Point2 uv) const {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) {
        return texel(0, 0);
    }
    // The image repeats: keep the fractional part first, so that huge (u, v) cannot overflow an index.
    // Continuous texel coordinates then have texel centres at integers + ½; row 0 is the top (v = 1).
    const double x = (uv.x - std::floor(uv.x)) * image_.width - 0.5;
    const double y = (1.0 - (uv.y - std::floor(uv.y))) * image_.height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double tx = x - fx, ty = y - fy;
    const auto ix = static_cast<long long>(fx), iy = static_cast<long long>(fy);
    return (1 - ty) * ((1 - tx) * texel(ix, iy) + tx * texel(ix + 1, iy)) +
           ty * ((1 - tx) * texel(ix, iy + 1) + tx * texel(ix + 1, iy + 1));
}

std::shared_ptr<const Texture> ImageTexture::create(Params& params, const BuildContext& context) {
    const std::string file = params.string("file");
    const std::filesystem::path path = context.resolve(file);
    Image image;
    try {
        image = load_texture_image(path);
    } catch (const std::exception& e) {
        params.fail("file", "cannot read texture image '" + path.string() + "': " + e.what());
    }
    if (image.width <= 0 || image.height <= 0) {
        params.fail("file", "texture image '" + path.string() + "' has no pixels");
    }
    return std::make_shared<ImageTexture>(std::move(image));
}

}  // namespace glint
