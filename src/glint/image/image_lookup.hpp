// Reading an image at a continuous (u, v): what image textures and normal maps share.
#pragma once

#include "glint/core/color.hpp"
#include "glint/core/vec.hpp"
#include "glint/image/image.hpp"

namespace glint {

// The image at (u, v), u left to right and v bottom to top over [0, 1], repeating outside, interpolated
// bilinearly between texel centres. A non-finite (u, v) reads the top-left texel. The image must have at
// least one pixel.
Rgb lookup_bilinear_repeat(const Image& image, Point2 uv);

}  // namespace glint
