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

    Rgb evaluate(const Hit& hit) const override { return lookup(hit.uv); }
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

// Reads a texture image as linear RGB: PNG, JPEG, BMP, TGA (8 or 16 bit, sRGB-decoded) and Radiance HDR
// through stb_image, OpenEXR through tinyexr (both already linear). Throws std::runtime_error with the
// reason when the file is missing or unreadable.
Image load_texture_image(const std::filesystem::path& path);

// The sRGB transfer function's inverse (IEC 61966-2-1): an encoded value in [0, 1] to linear.
double srgb_to_linear(double encoded);

}  // namespace glint
