#include "glint/image/image_lookup.hpp"

#include <cmath>

namespace glint {

namespace {
Rgb texel(const Image& image, long long x, long long y) {  // with wrap-around
    const auto wrap = [](long long i, long long n) { return ((i % n) + n) % n; };
    const float* p =
        image.pixel(static_cast<int>(wrap(x, image.width)), static_cast<int>(wrap(y, image.height)));
    return {p[0], p[1], p[2]};
}
}  // namespace

Rgb lookup_bilinear_repeat(const Image& image, Point2 uv) {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) {
        return texel(image, 0, 0);
    }
    // The image repeats: keep the fractional part first, so that huge (u, v) cannot overflow an index.
    // Continuous texel coordinates then have texel centres at integers + ½; row 0 is the top (v = 1).
    const double x = (uv.x - std::floor(uv.x)) * image.width - 0.5;
    const double y = (1.0 - (uv.y - std::floor(uv.y))) * image.height - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const double tx = x - fx, ty = y - fy;
    const auto ix = static_cast<long long>(fx), iy = static_cast<long long>(fy);
    return (1 - ty) * ((1 - tx) * texel(image, ix, iy) + tx * texel(image, ix + 1, iy)) +
           ty * ((1 - tx) * texel(image, ix, iy + 1) + tx * texel(image, ix + 1, iy + 1));
}

}  // namespace glint
