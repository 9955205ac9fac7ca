// The one name → constructor table of textures, and the reader that lets every colour parameter be a
// texture. Adding a texture: a file here and a line in the table.
#include <algorithm>

#include "glint/params/build_context.hpp"
#include "glint/params/name_table.hpp"
#include "glint/params/params.hpp"
#include "glint/texture/checker.hpp"
#include "glint/texture/image_texture.hpp"
#include "glint/texture/noise.hpp"

namespace glint {

namespace {

// {type: constant, value: [r, g, b]}: the long form of a plain colour.
std::shared_ptr<const Texture> create_constant(Params& params, const BuildContext&) {
    return std::make_shared<ConstantTexture>(params.color("value"));
}

}  // namespace

const NameTable<TextureEntry>& texture_table() {
    static const NameTable<TextureEntry> table = {
        {"constant", &create_constant},
        {"checker", &CheckerTexture::create},
        {"image", &ImageTexture::create},
        {"noise", &NoiseTexture::create},
    };
    return table;
}

std::shared_ptr<const Texture> read_texture(Params& params, const std::string& key, const Rgb& fallback,
                                            const BuildContext& context) {
    const Node* node = params.node(key);
    std::shared_ptr<const Texture> texture;
    if (!node) {
        texture = std::make_shared<ConstantTexture>(fallback);
    } else if (!node->is_map()) {
        texture = std::make_shared<ConstantTexture>(node_color(*node, params.what() + "." + key));
    } else {
        texture = build_object(texture_table(), *node, params.what() + "." + key, "texture", context);
    }
    if (texture->min_value() < 0) {
        params.fail(key, params.what() + "." + key + " must not be negative");
    }
    return texture;
}

std::shared_ptr<const Texture> read_reflectance(Params& params, const std::string& key, const Rgb& fallback,
                                                const BuildContext& context) {
    auto texture = read_texture(params, key, fallback, context);
    if (texture->max_value() > 1) {
        params.fail(key, params.what() + "." + key +
                             " is a reflectance and must lie in [0, 1] per channel (a surface cannot reflect "
                             "more light than it receives)");
    }
    return texture;
}

}  // namespace glint
