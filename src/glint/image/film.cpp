#include "glint/image/film.hpp"

#include <algorithm>

namespace glint {

Film::Film(int width, int height)
    : width_(width), height_(height), pixels_(static_cast<size_t>(width) * static_cast<size_t>(height)) {}

Rgb Film::pixel(int x, int y) const {
    const Pixel& p = pixels_[static_cast<size_t>(y) * width_ + x];
    return p.count ? p.sum / static_cast<double>(p.count) : Rgb{};
}

double Film::mean_variance(int x, int y) const {
    const Pixel& p = pixels_[static_cast<size_t>(y) * width_ + x];
    if (p.count < 2) {
        return 0;
    }
    const double n = static_cast<double>(p.count);
    const double sum = p.sum.luminance();
    return std::max(0.0, (p.luminance_squares - sum * sum / n) / (n * (n - 1)));
}

void Film::clear() {
    std::fill(pixels_.begin(), pixels_.end(), Pixel{});
}

Image Film::to_image() const {
    return to_image(0, 0, width_, height_);
}

Image Film::to_image(int x0, int y0, int width, int height) const {
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const Rgb c = pixel(x0 + x, y0 + y);
            float* out = image.pixel(x, y);
            out[0] = static_cast<float>(c.r);
            out[1] = static_cast<float>(c.g);
            out[2] = static_cast<float>(c.b);
        }
    }
    return image;
}

}  // namespace glint
