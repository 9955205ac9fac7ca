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
    explicit ImageTexture(Image image);

    Rgb evaluate(const Hit& hit) const override { return lookup(surface_uv(hit)); }
    Rgb lookup(Point2 uv) const;
    double min_value() const override { return min_; }
    double max_value() const override { return max_; }

    // {type: image, file: name.png}
    static std::shared_ptr<const Texture> create(Params& params, const BuildContext& context);

  private:
    Rgb texel(long long x, long long y) const;  // with wrap-around

    Image image_;
    double min_ = 0, max_ = 0;
};

}  // namespace glint
