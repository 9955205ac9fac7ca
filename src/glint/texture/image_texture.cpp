// Image {type: image, file: x.png}: `file` resolves against the scene file's folder. 8- and 16-bit files
// are sRGB-decoded; HDR, EXR and PFM are taken as linear. A missing, unreadable, oversized or truncated
// file is an error at `file` (read_image checks the header before decoding).
#include "glint/texture/image_texture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "glint/geometry/mesh_io/gltf_file.hpp"
#include "glint/image/image_io.hpp"
#include "glint/params/build_context.hpp"
#include "glint/params/params.hpp"

namespace glint {

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
        if (params.has("gltf_image")) {
            // An image stored inside a glTF model: its encoded bytes, decoded by the same reader.
            const std::int64_t index = params.integer("gltf_image");
            if (index < 0 || index > std::numeric_limits<int>::max()) {
                params.fail("gltf_image", "gltf_image must be a whole number ≥ 0");
            }
            const auto model = load_gltf_file(path, params.pos_of("file"));
            image =
                decode_image(gltf_image_bytes(*model, static_cast<int>(index), params.pos_of("gltf_image")),
                             path.string() + " image " + std::to_string(index));
        } else {
            image = read_image(path);
        }
    } catch (const SceneError&) {
        throw;
    } catch (const std::exception& e) {
        // The reader's message starts with the file's path.
        params.fail("file", std::string("cannot read texture image: ") + e.what());
    }
    if (image.width <= 0 || image.height <= 0) {
        params.fail("file", "texture image '" + path.string() + "' has no pixels");
    }
    return std::make_shared<ImageTexture>(std::move(image));
}

}  // namespace glint
