#pragma once

#include <filesystem>
#include <memory>

#include "glint/image/image.hpp"
#include "glint/texture/texture.hpp"

namespace glint {

// An image mapped onto the surface by (u, v): u runs left to right, v bottom to top, and the image
// repeats outside [0, 1]. Values are interpolated bilinearly between texel centres.
class ImageTexture final : public Texture {
  public:
    // Which of the file's channels the texture gives: all three (a colour), or one of them in every
    // channel (a grey texture: a number such as glTF's metallic, stored in the blue channel).
    enum class Channel { Rgb, R, G, B };

    // The texture reads `image` through `channel`, times `scale` per channel (≥ 0). Both are applied
    // once, here, to the stored texels, so a lookup costs the same with them as without.
    explicit ImageTexture(Image image, Channel channel = Channel::Rgb, const Rgb& scale = Rgb(1.0));

    Rgb evaluate(const Hit& hit) const override { return lookup(surface_uv(hit)); }
    Rgb lookup(Point2 uv) const;
    double min_value() const override { return min_; }
    double max_value() const override { return max_; }

    // {type: image, file: name.png, channel: rgb | r | g | b, scale: colour, encoding: srgb | linear}
    static std::shared_ptr<const Texture> create(Params& params, const BuildContext& context);

  private:
    Image image_;
    double min_ = 0, max_ = 0;
};

}  // namespace glint
