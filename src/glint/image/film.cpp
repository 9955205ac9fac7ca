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
    Image image(width_, height_);
    for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) {
            const Rgb c = pixel(x, y);
            float* out = image.pixel(x, y);
            out[0] = static_cast<float>(c.r);
            out[1] = static_cast<float>(c.g);
            out[2] = static_cast<float>(c.b);
        }
    }
    return image;
}

}  // namespace glint
