#include "glint/image/image_io.hpp"

#include <gtest/gtest.h>

#include "test_util.hpp"

namespace glint {
namespace {

TEST(ImageIo, PfmRoundTripsExactly) {
    test::TempDir dir;
    Image image(3, 2);
    for (size_t i = 0; i < image.rgb.size(); ++i) {
        image.rgb[i] = 0.1f * static_cast<float>(i) + 1e-7f;
    }
    image.pixel(2, 1)[0] = 1234.5f;  // radiance above 1 is kept
    write_image(image, dir / "x.pfm");
    const Image back = read_pfm(dir / "x.pfm");
    EXPECT_EQ(back.width, 3);
    EXPECT_EQ(back.height, 2);
    EXPECT_EQ(back.rgb, image.rgb);
}

TEST(ImageIo, SrgbEncodingOfKnownValues) {
    EXPECT_EQ(linear_to_srgb8(0.0f), 0);
    EXPECT_EQ(linear_to_srgb8(1.0f), 255);
    EXPECT_EQ(linear_to_srgb8(7.0f), 255);  // clamped
    EXPECT_EQ(linear_to_srgb8(-1.0f), 0);   // clamped
    EXPECT_EQ(linear_to_srgb8(0.5f), 188);  // 1.055 · 0.5^(1/2.4) − 0.055 = 0.7354
    EXPECT_EQ(linear_to_srgb8(0.002f), 7);  // linear segment: 12.92 · 0.002 · 255 = 6.6
}

TEST(ImageIo, FormatsFollowTheExtension) {
    EXPECT_EQ(image_format_for("a.PNG"), ImageFormat::Png);
    EXPECT_EQ(image_format_for("dir/a.exr"), ImageFormat::Exr);
    EXPECT_EQ(image_format_for("a.pfm"), ImageFormat::Pfm);
    EXPECT_FALSE(image_format_for("a.jpg"));
    EXPECT_FALSE(image_format_for("png"));
}

TEST(ImageIo, EncodersProduceTheirMagicNumbers) {
    Image image(4, 4);
    const auto png = encode_png(image);
    ASSERT_GT(png.size(), 8u);
    EXPECT_EQ(png[1], 'P');
    EXPECT_EQ(png[2], 'N');
    const auto exr = encode_exr(image);
    ASSERT_GT(exr.size(), 4u);
    EXPECT_EQ(exr[0], 0x76);  // OpenEXR magic 20000630 = 0x762f3101, little-endian
    EXPECT_EQ(exr[1], 0x2f);
}

TEST(ImageIo, AtomicWriteLeavesNoTemporaryAndReplacesTheOldFile) {
    test::TempDir dir;
    dir.write("x.png", "old contents");
    Image image(2, 2);
    write_image(image, dir / "x.png");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
    EXPECT_NE(std::filesystem::file_size(dir / "x.png"), 12u);
}

TEST(ImageIo, UnwritableTargetThrowsAndLeavesNothing) {
    Image image(2, 2);
    EXPECT_THROW(write_image(image, "/nonexistent-dir/x.png"), ImageWriteError);
}

}  // namespace
}  // namespace glint
