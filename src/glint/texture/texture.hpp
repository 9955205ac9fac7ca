// Textures: a colour that varies over a surface (paper §VI's "colour" parameters, made spatial).
//
// Any colour parameter of a material accepts either a colour ([r, g, b] or one number) or a texture map
// {type: checker | image | noise | constant, …}. A texture is evaluated at a Hit: solid textures use
// hit.point (world space), surface textures surface_uv(hit).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "glint/core/color.hpp"
#include "glint/geometry/hit.hpp"
#include "glint/params/name_table.hpp"

namespace glint {

class Params;
struct BuildContext;

class Texture {
  public:
    virtual ~Texture() = default;
    virtual Rgb evaluate(const Hit& hit) const = 0;
    // Bounds on every value the texture can return, over all channels: scene building checks them
    // (a reflectance must stay in [0, 1], no colour may be negative).
    virtual double min_value() const = 0;
    virtual double max_value() const = 0;
};

// The same colour everywhere: what a plain colour parameter becomes.
class ConstantTexture final : public Texture {
  public:
    explicit ConstantTexture(const Rgb& value) : value_(value) {}
    Rgb evaluate(const Hit&) const override { return value_; }
    double min_value() const override { return std::min({value_.r, value_.g, value_.b}); }
    double max_value() const override { return value_.max_component(); }

  private:
    Rgb value_;
};

using TextureFactory = std::function<std::shared_ptr<const Texture>(Params&, const BuildContext&)>;
struct TextureEntry {
    std::string name;
    TextureFactory create;
};
// The name → constructor table of textures ("constant", "checker", "image", "noise").
const NameTable<TextureEntry>& texture_table();

// The colour parameter `key` of `params`: a colour, a texture map, or `fallback` when absent.
// Negative values are an error at the key's position.
std::shared_ptr<const Texture> read_texture(Params& params, const std::string& key, const Rgb& fallback,
                                            const BuildContext& context);
// As read_texture, for reflectances: every value must also be at most 1 (a surface cannot reflect more
// light than it receives).
std::shared_ptr<const Texture> read_reflectance(Params& params, const std::string& key, const Rgb& fallback,
                                                const BuildContext& context);

}  // namespace glint
