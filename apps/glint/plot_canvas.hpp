// A small rasteriser for the figures `glint samples` draws (pattern plots, convergence plots):
// antialiased disks and lines, rectangles and a 5 × 7 bitmap font. Colours are sRGB in [0, 1];
// image() converts to the linear glint::Image that write_image encodes back to sRGB.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "glint/image/image.hpp"

namespace glint_cli {

using Colour = std::array<float, 3>;  // sRGB-encoded

class Canvas {
  public:
    Canvas(int width, int height, Colour background);
    int width() const { return width_; }
    int height() const { return height_; }

    // Pixel (x, y) covers [x, x+1) × [y, y+1); coordinates are continuous.
    void fill_rect(double x0, double y0, double x1, double y1, Colour colour);
    void line(double x0, double y0, double x1, double y1, double thickness, Colour colour);
    void disk(double cx, double cy, double radius, Colour colour);
    // Text with its top-left corner at (x, y); each font pixel is `scale` pixels. Returns the width.
    double text(double x, double y, const std::string& s, Colour colour, int scale = 2);
    static double text_width(const std::string& s, int scale = 2) { return s.size() * 6.0 * scale; }

    glint::Image image() const;

  private:
    void blend(int x, int y, Colour colour, double coverage);
    int width_, height_;
    std::vector<float> srgb_;
};

}  // namespace glint_cli
