#include "plot_canvas.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>

namespace glint_cli {
namespace {

// 5 × 7 glyphs, one byte per row, bit 4 the leftmost column. Upper case is drawn as lower case.
struct Glyph {
    char c;
    std::uint8_t rows[7];
};
constexpr Glyph kFont[] = {
    {'0', {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E}}, {'1', {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'2', {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F}}, {'3', {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E}},
    {'4', {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02}}, {'5', {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E}},
    {'6', {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E}}, {'7', {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08}},
    {'8', {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E}}, {'9', {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C}},
    {'a', {0x00, 0x00, 0x0E, 0x01, 0x0F, 0x11, 0x0F}}, {'b', {0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x1E}},
    {'c', {0x00, 0x00, 0x0E, 0x10, 0x10, 0x11, 0x0E}}, {'d', {0x01, 0x01, 0x0D, 0x13, 0x11, 0x11, 0x0F}},
    {'e', {0x00, 0x00, 0x0E, 0x11, 0x1F, 0x10, 0x0E}}, {'f', {0x06, 0x09, 0x08, 0x1C, 0x08, 0x08, 0x08}},
    {'g', {0x00, 0x00, 0x0F, 0x11, 0x0F, 0x01, 0x0E}}, {'h', {0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x11}},
    {'i', {0x04, 0x00, 0x0C, 0x04, 0x04, 0x04, 0x0E}}, {'j', {0x02, 0x00, 0x06, 0x02, 0x02, 0x12, 0x0C}},
    {'k', {0x10, 0x10, 0x12, 0x14, 0x18, 0x14, 0x12}}, {'l', {0x0C, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0E}},
    {'m', {0x00, 0x00, 0x1A, 0x15, 0x15, 0x11, 0x11}}, {'n', {0x00, 0x00, 0x16, 0x19, 0x11, 0x11, 0x11}},
    {'o', {0x00, 0x00, 0x0E, 0x11, 0x11, 0x11, 0x0E}}, {'p', {0x00, 0x00, 0x1E, 0x11, 0x11, 0x1E, 0x10}},
    {'q', {0x00, 0x00, 0x0D, 0x13, 0x0F, 0x01, 0x01}}, {'r', {0x00, 0x00, 0x16, 0x19, 0x10, 0x10, 0x10}},
    {'s', {0x00, 0x00, 0x0E, 0x10, 0x0E, 0x01, 0x1E}}, {'t', {0x08, 0x08, 0x1C, 0x08, 0x08, 0x09, 0x06}},
    {'u', {0x00, 0x00, 0x11, 0x11, 0x11, 0x13, 0x0D}}, {'v', {0x00, 0x00, 0x11, 0x11, 0x11, 0x0A, 0x04}},
    {'w', {0x00, 0x00, 0x11, 0x11, 0x15, 0x15, 0x0A}}, {'x', {0x00, 0x00, 0x11, 0x0A, 0x04, 0x0A, 0x11}},
    {'y', {0x00, 0x00, 0x11, 0x11, 0x0F, 0x01, 0x0E}}, {'z', {0x00, 0x00, 0x1F, 0x02, 0x04, 0x08, 0x1F}},
    {'-', {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00}}, {'.', {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C}},
    {'^', {0x04, 0x0A, 0x11, 0x00, 0x00, 0x00, 0x00}}, {'=', {0x00, 0x00, 0x1F, 0x00, 0x1F, 0x00, 0x00}},
    {'(', {0x02, 0x04, 0x08, 0x08, 0x08, 0x04, 0x02}}, {')', {0x08, 0x04, 0x02, 0x02, 0x02, 0x04, 0x08}},
    {',', {0x00, 0x00, 0x00, 0x00, 0x0C, 0x04, 0x08}}, {':', {0x00, 0x0C, 0x0C, 0x00, 0x0C, 0x0C, 0x00}},
    {'/', {0x00, 0x01, 0x02, 0x04, 0x08, 0x10, 0x00}}, {'+', {0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00}},
};

const Glyph* find_glyph(char c) {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const Glyph& g : kFont) {
        if (g.c == c) {
            return &g;
        }
    }
    return nullptr;  // spaces and unknown characters draw nothing
}

float srgb_to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

Canvas::Canvas(int width, int height, Colour background)
    : width_(width), height_(height), srgb_(static_cast<size_t>(width) * height * 3) {
    for (size_t i = 0; i < srgb_.size(); ++i) {
        srgb_[i] = background[i % 3];
    }
}

void Canvas::blend(int x, int y, Colour colour, double coverage) {
    if (x < 0 || y < 0 || x >= width_ || y >= height_ || coverage <= 0) {
        return;
    }
    const auto a = static_cast<float>(std::min(coverage, 1.0));
    float* p = &srgb_[(static_cast<size_t>(y) * width_ + x) * 3];
    for (int c = 0; c < 3; ++c) {
        p[c] = p[c] * (1 - a) + colour[c] * a;
    }
}

void Canvas::fill_rect(double x0, double y0, double x1, double y1, Colour colour) {
    for (int y = static_cast<int>(std::floor(y0)); y < std::ceil(y1); ++y) {
        const double cy = std::min<double>(y + 1, y1) - std::max<double>(y, y0);
        for (int x = static_cast<int>(std::floor(x0)); x < std::ceil(x1); ++x) {
            const double cx = std::min<double>(x + 1, x1) - std::max<double>(x, x0);
            blend(x, y, colour, cx * cy);
        }
    }
}

void Canvas::line(double x0, double y0, double x1, double y1, double thickness, Colour colour) {
    const double half = thickness / 2;
    const double dx = x1 - x0, dy = y1 - y0, length2 = dx * dx + dy * dy;
    const int xa = static_cast<int>(std::floor(std::min(x0, x1) - half - 1));
    const int xb = static_cast<int>(std::ceil(std::max(x0, x1) + half + 1));
    const int ya = static_cast<int>(std::floor(std::min(y0, y1) - half - 1));
    const int yb = static_cast<int>(std::ceil(std::max(y0, y1) + half + 1));
    for (int y = std::max(ya, 0); y <= std::min(yb, height_ - 1); ++y) {
        for (int x = std::max(xa, 0); x <= std::min(xb, width_ - 1); ++x) {
            const double px = x + 0.5 - x0, py = y + 0.5 - y0;
            const double t = length2 > 0 ? std::clamp((px * dx + py * dy) / length2, 0.0, 1.0) : 0.0;
            const double distance = std::hypot(px - t * dx, py - t * dy);
            // Coverage of a pixel by the thick segment, approximated by its distance to the centre.
            blend(x, y, colour, std::clamp(half + 0.5 - distance, 0.0, 1.0) * std::min(1.0, thickness));
        }
    }
}

void Canvas::disk(double cx, double cy, double radius, Colour colour) {
    for (int y = static_cast<int>(std::floor(cy - radius - 1)); y <= cy + radius + 1; ++y) {
        for (int x = static_cast<int>(std::floor(cx - radius - 1)); x <= cx + radius + 1; ++x) {
            const double distance = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
            blend(x, y, colour, std::clamp(radius + 0.5 - distance, 0.0, 1.0));
        }
    }
}

double Canvas::text(double x, double y, const std::string& s, Colour colour, int scale) {
    for (size_t i = 0; i < s.size(); ++i) {
        const Glyph* glyph = find_glyph(s[i]);
        if (glyph == nullptr) {
            continue;
        }
        const double gx = x + static_cast<double>(i) * 6 * scale;
        for (int row = 0; row < 7; ++row) {
            for (int column = 0; column < 5; ++column) {
                if (glyph->rows[row] & (0x10 >> column)) {
                    fill_rect(gx + column * scale, y + row * scale, gx + (column + 1) * scale,
                              y + (row + 1) * scale, colour);
                }
            }
        }
    }
    return text_width(s, scale);
}

glint::Image Canvas::image() const {
    glint::Image out(width_, height_);
    for (size_t i = 0; i < srgb_.size(); ++i) {
        out.rgb[i] = srgb_to_linear(srgb_[i]);
    }
    return out;
}

}  // namespace glint_cli
