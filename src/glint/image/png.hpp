// glint's PNG writer (png.cpp), for encode_png and for the tests and measurements of its parameters:
// 8-bit RGB, each row filtered (PNG's five filters) and the whole deflated by zlib. encode_png
// (image_io.hpp) uses the default PngEncoding, which png.cpp explains with the figures it was chosen by.
#pragma once

#include <span>
#include <vector>

namespace glint {

// A PNG row filter (PNG specification, section 9.2), or the per-row choice among the five.
enum class PngRowFilter {
    None,
    Sub,
    Up,
    Average,
    Paeth,
    // Each row with the filter whose output bytes, read as signed, have the smallest sum of absolute
    // values (the PNG specification's suggestion, section 12.8): small differences deflate better.
    SmallestSum,
};

// zlib's deflate strategies (zlib.h), named here so that this header does not include zlib.h.
enum class PngDeflateStrategy { Default, Filtered, Rle, HuffmanOnly };

struct PngEncoding {
    PngRowFilter filter = PngRowFilter::SmallestSum;
    int level = 6;  // zlib's 1 (fastest) to 9 (smallest); run-length deflate (Rle) does not use it
    PngDeflateStrategy strategy = PngDeflateStrategy::Rle;
};

// What glint's PNG files (glint render -o x.png) are written with: rendered pictures are often smooth
// (skies, soft shadows), where zlib's filtered deflate makes files 8 % smaller than run-length deflate
// over the gallery's pictures (2.3x on umbra-penumbra's), in about 9 ms more a picture (png.cpp).
inline constexpr PngEncoding kPngFileEncoding{PngRowFilter::SmallestSum, 6, PngDeflateStrategy::Filtered};
// What the preview's frames are written with, once a pass: the default, run-length deflate, fastest
// and for noisy frames also the smallest (png.cpp).
inline constexpr PngEncoding kPngFrameEncoding{};

// The PNG file of `rgb`: width × height pixels of 3 bytes (R, G, B; sRGB as stored), row by row, top
// first. Throws ImageWriteError when the sizes disagree or zlib fails.
std::vector<unsigned char> encode_png_rgb8(std::span<const unsigned char> rgb, int width, int height,
                                           const PngEncoding& encoding = {});

}  // namespace glint
