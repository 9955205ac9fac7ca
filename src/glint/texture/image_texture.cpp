// Image {type: image, file: x.png, channel, scale, encoding}: `file` resolves against the scene file's
// folder. 8- and 16-bit files are sRGB-decoded (`encoding: srgb`, the default) or taken as they are
// (`encoding: linear`, for data: glTF's metallic-roughness maps); HDR, EXR and PFM are linear either way.
// `channel` r, g or b makes a grey texture of that channel; `scale` multiplies (glTF's factors). A
// missing, unreadable, oversized or truncated file is an error at `file` (read_image_keys).
#include "glint/texture/image_texture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "glint/geometry/mesh_io/gltf_file.hpp"
#include "glint/image/image_io.hpp"
#include "glint/image/image_lookup.hpp"
#include "glint/params/build_context.hpp"
#include "glint/params/params.hpp"

namespace glint {

ImageTexture::ImageTexture(Image image, Channel channel, const Rgb& scale) : image_(std::move(image)) {
    if (image_.width <= 0 || image_.height <= 0) {
        throw std::invalid_argument("an image texture needs at least one pixel");
    }
    if (channel != Channel::Rgb || scale != Rgb(1.0)) {
        const int source = channel == Channel::R ? 0 : channel == Channel::G ? 1 : 2;
        for (std::size_t i = 0; i < image_.rgb.size(); i += 3) {
            const float grey = image_.rgb[i + static_cast<std::size_t>(source)];
            for (std::size_t c = 0; c < 3; ++c) {
                const double value = channel == Channel::Rgb ? image_.rgb[i + c] : grey;
                image_.rgb[i + c] = static_cast<float>(value * scale[static_cast<int>(c)]);
            }
        }
    }
    const auto [lo, hi] = std::minmax_element(image_.rgb.begin(), image_.rgb.end());
    min_ = *lo;
    max_ = *hi;
}

Rgb ImageTexture::lookup(Point2 uv) const {
    return lookup_bilinear_repeat(image_, uv);
}

std::shared_ptr<const Texture> ImageTexture::create(Params& params, const BuildContext& context) {
    static const EnumTable<Channel> channels = {
        {"rgb", Channel::Rgb}, {"r", Channel::R}, {"g", Channel::G}, {"b", Channel::B}};
    static const EnumTable<bool> encodings = {{"srgb", true}, {"linear", false}};
    const Channel channel = params.enumeration("channel", channels, Channel::Rgb);
    const Rgb scale = params.non_negative_color("scale", Rgb(1.0));
    const bool srgb = params.enumeration("encoding", encodings, true);
    Image image = read_image_keys(params, context, srgb);
    return std::make_shared<ImageTexture>(std::move(image), channel, scale);
}

}  // namespace glint
