// JPEG decoding (src/glint/image/jpeg.cpp) against files written here by libjpeg's encoder: flat
// colours whose linear values are known from the sRGB curve, grey, Adobe CMYK, and a progressive file
// with more scans than glint decodes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdio>  // before jpeglib.h, which uses size_t and FILE without including their headers
#include <cstdlib>
#include <string>
#include <vector>

#include <jpeglib.h>

#include "glint/image/image_io.hpp"

namespace glint {
namespace {

struct Encoding {
    int width = 16, height = 16;
    int components = 3;
    J_COLOR_SPACE color_space = JCS_RGB;
    bool adobe_marker = false;
    std::vector<jpeg_scan_info> scans;  // empty: baseline
};

// Every pixel `pixel` (one sample per component), at quality 100.
std::vector<unsigned char> encode(const Encoding& encoding, const std::vector<unsigned char>& pixel) {
    jpeg_compress_struct info{};
    jpeg_error_mgr errors{};
    info.err = jpeg_std_error(&errors);  // the encoder is given valid input: its errors exit the test
    jpeg_create_compress(&info);
    unsigned char* buffer = nullptr;
    unsigned long length = 0;
    jpeg_mem_dest(&info, &buffer, &length);
    info.image_width = static_cast<JDIMENSION>(encoding.width);
    info.image_height = static_cast<JDIMENSION>(encoding.height);
    info.input_components = encoding.components;
    info.in_color_space = encoding.color_space;
    jpeg_set_defaults(&info);
    jpeg_set_quality(&info, 100, TRUE);
    info.write_Adobe_marker = encoding.adobe_marker ? TRUE : FALSE;
    if (!encoding.scans.empty()) {
        info.scan_info = encoding.scans.data();
        info.num_scans = static_cast<int>(encoding.scans.size());
    }
    jpeg_start_compress(&info, TRUE);
    std::vector<unsigned char> row;
    for (int x = 0; x < encoding.width; ++x) {
        row.insert(row.end(), pixel.begin(), pixel.end());
    }
    while (info.next_scanline < info.image_height) {
        JSAMPROW rows[1] = {row.data()};
        jpeg_write_scanlines(&info, rows, 1);
    }
    jpeg_finish_compress(&info);
    jpeg_destroy_compress(&info);
    std::vector<unsigned char> bytes(buffer, buffer + length);
    std::free(buffer);
    return bytes;
}

double linear(int srgb_byte) {
    return srgb_to_linear(srgb_byte / 255.0);
}

// A flat colour survives JPEG at quality 100 within a step or two of its 8-bit value.
void expect_colour(const Image& image, double r, double g, double b, double tolerance) {
    for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
        ASSERT_NEAR(image.rgb[i], r, tolerance) << "pixel " << i / 3;
        ASSERT_NEAR(image.rgb[i + 1], g, tolerance) << "pixel " << i / 3;
        ASSERT_NEAR(image.rgb[i + 2], b, tolerance) << "pixel " << i / 3;
    }
}

// Two 8-bit steps at the value: the sRGB curve's slope bounds what a step is worth.
double two_steps(int srgb_byte) {
    return std::abs(linear(std::min(srgb_byte + 2, 255)) - linear(srgb_byte)) + 1e-6;
}

TEST(Jpeg, AFlatRgbColourDecodesToItsLinearValue) {
    const Image image = decode_image(encode({}, {200, 100, 30}), "flat.jpg");
    ASSERT_EQ(image.width, 16);
    ASSERT_EQ(image.height, 16);
    expect_colour(image, linear(200), linear(100), linear(30), two_steps(200));
}

TEST(Jpeg, GreyFillsAllThreeChannels) {
    Encoding grey;
    grey.components = 1;
    grey.color_space = JCS_GRAYSCALE;
    const Image image = decode_image(encode(grey, {128}), "grey.jpg");
    expect_colour(image, linear(128), linear(128), linear(128), two_steps(128));
}

TEST(Jpeg, AdobeCmykIsConvertedToRgb) {
    // Photoshop's CMYK files store 255 − ink. Stored (255, 0, 0, 255): no cyan, full magenta and yellow,
    // no black, which is red.
    Encoding cmyk;
    cmyk.components = 4;
    cmyk.color_space = JCS_CMYK;
    cmyk.adobe_marker = true;
    const Image image = decode_image(encode(cmyk, {255, 0, 0, 255}), "cmyk.jpg");
    expect_colour(image, 1.0, 0.0, 0.0, 0.01);
}

// A progressive script for one component in `levels` successive-approximation steps: the DC
// coefficient and each of the 63 AC coefficients in a band of its own.
std::vector<jpeg_scan_info> successive_approximation(int levels) {
    std::vector<jpeg_scan_info> scans;
    const auto scan = [&](int ss, int se, int ah, int al) {
        jpeg_scan_info info{};
        info.comps_in_scan = 1;
        info.component_index[0] = 0;
        info.Ss = ss;
        info.Se = se;
        info.Ah = ah;
        info.Al = al;
        scans.push_back(info);
    };
    const int top = levels - 1;
    scan(0, 0, 0, top);
    for (int al = top - 1; al >= 0; --al) {
        scan(0, 0, al + 1, al);
    }
    for (int k = 1; k <= 63; ++k) {
        scan(k, k, 0, top);
        for (int al = top - 1; al >= 0; --al) {
            scan(k, k, al + 1, al);
        }
    }
    return scans;
}

// A 16 × 16 grey progressive file of levels × 64 scans.
std::vector<unsigned char> grey_progressive(int levels) {
    Encoding progressive;
    progressive.components = 1;
    progressive.color_space = JCS_GRAYSCALE;
    progressive.scans = successive_approximation(levels);
    return encode(progressive, {77});
}

TEST(Jpeg, ProgressiveFilesDecodeUpToTheScanLimit) {
    const Image image = decode_image(grey_progressive(2), "progressive.jpg");  // 128 scans
    expect_colour(image, linear(77), linear(77), linear(77), two_steps(77));
}

TEST(Jpeg, ProgressiveFilesWithMoreThan500ScansAreRefused) {
    // Each scan is a pass over every block, so a small file of many scans would take minutes to
    // decode at a large size. 8 × 64 = 512 valid scans.
    const std::vector<unsigned char> bytes = grey_progressive(8);
    try {
        decode_image(bytes, "scans.jpg");
        ADD_FAILURE() << "a JPEG of 512 scans was read";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(
            std::string(error.what()).find("scans.jpg: cannot decode the JPEG file (more than 500 scans)"),
            std::string::npos)
            << error.what();
    }
}

TEST(Jpeg, CorruptEntropyCodedDataIsAnErrorNotAGreyPatch) {
    // libjpeg fills what it cannot decode with grey and warns; glint refuses the file.
    std::vector<unsigned char> bytes = encode({}, {200, 100, 30});
    std::size_t scan = 0;
    for (std::size_t i = 0; i + 1 < bytes.size(); ++i) {
        if (bytes[i] == 0xff && bytes[i + 1] == 0xda) {
            scan = i;
        }
    }
    ASSERT_NE(scan, 0u);
    bytes.resize(scan + 20);  // the scan header and a few bytes of data, then nothing
    EXPECT_THROW(decode_image(bytes, "cut.jpg"), std::runtime_error);
}

}  // namespace
}  // namespace glint
