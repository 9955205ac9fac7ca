// Textures: checker cells at known points, bilinear image lookup of tiny images written here, Perlin
// noise's known properties (zero on the lattice, bounded, deterministic).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "glint/core/hash.hpp"
#include "glint/image/image_io.hpp"
#include "glint/params/build_context.hpp"
#include "glint/texture/checker.hpp"
#include "glint/texture/image_texture.hpp"
#include "glint/texture/noise.hpp"

namespace glint {
namespace {

Hit hit_at(const Vec3& point, Point2 uv = {}) {
    Hit hit;
    hit.point = point;
    hit.normal = hit.shading_normal = Vec3{0, 1, 0};
    hit.uv = uv;
    return hit;
}

std::shared_ptr<const Texture> constant(const Rgb& c) {
    return std::make_shared<ConstantTexture>(c);
}

const Rgb kEven{1, 0, 0}, kOdd{0, 0, 1};

TEST(CheckerTexture, UvCellsAlternate) {
    const CheckerTexture checker(constant(kEven), constant(kOdd), 2.0, CheckerTexture::Space::Uv);
    EXPECT_EQ(checker.evaluate(hit_at({}, {0.1, 0.1})), kEven);  // cell (0, 0)
    EXPECT_EQ(checker.evaluate(hit_at({}, {0.6, 0.1})), kOdd);   // cell (1, 0)
    EXPECT_EQ(checker.evaluate(hit_at({}, {0.1, 0.6})), kOdd);   // cell (0, 1)
    EXPECT_EQ(checker.evaluate(hit_at({}, {0.6, 0.9})), kEven);  // cell (1, 1)
    EXPECT_EQ(checker.min_value(), 0.0);
    EXPECT_EQ(checker.max_value(), 1.0);
}

TEST(CheckerTexture, SolidCellsAlternateInThreeDimensions) {
    const CheckerTexture checker(constant(kEven), constant(kOdd), 1.0, CheckerTexture::Space::Solid);
    EXPECT_EQ(checker.evaluate(hit_at({0.5, 0.5, 0.5})), kEven);
    EXPECT_EQ(checker.evaluate(hit_at({1.5, 0.5, 0.5})), kOdd);
    EXPECT_EQ(checker.evaluate(hit_at({1.5, 1.5, 0.5})), kEven);
    EXPECT_EQ(checker.evaluate(hit_at({1.5, 1.5, 1.5})), kOdd);
    EXPECT_EQ(checker.evaluate(hit_at({-0.5, 0.5, 0.5})),
              kOdd);  // negative coordinates: floor, not truncation
    // scale 4: cells a quarter unit wide.
    const CheckerTexture fine(constant(kEven), constant(kOdd), 4.0, CheckerTexture::Space::Solid);
    EXPECT_EQ(fine.evaluate(hit_at({0.3, 0.1, 0.1})), kOdd);
}

TEST(CheckerTexture, AFloorOnACellBoundaryIsNotSpeckled) {
    // Points of the plane y = 0 come back with y = ±1e-17 from rounding: all must get the same cell.
    const CheckerTexture checker(constant(kEven), constant(kOdd), 1.0, CheckerTexture::Space::Solid);
    EXPECT_EQ(checker.evaluate(hit_at({0.5, 1e-17, 0.5})), checker.evaluate(hit_at({0.5, -1e-17, 0.5})));
}

TEST(CheckerTexture, FarPointsOfAnInfinitePlaneStillGetACell) {
    // Beyond 2⁵³ every double is an even integer: cell parity 0, and no integer overflow on the way.
    const CheckerTexture checker(constant(kEven), constant(kOdd), 1.0, CheckerTexture::Space::Solid);
    EXPECT_EQ(checker.evaluate(hit_at({1e30, 0.5, -1e25})), kEven);
    EXPECT_EQ(checker.evaluate(hit_at({1e30, 1.5, -1e25})), kOdd);
    EXPECT_EQ(checker.evaluate(hit_at({-3.5, 0.5, 0.5})), kEven);  // cell −4: even
}

// A 2 × 2 image: top row red, green; bottom row blue, white.
Image two_by_two() {
    Image image(2, 2);
    const float colors[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    for (int i = 0; i < 4; ++i) {
        std::copy(colors[i], colors[i] + 3, image.pixel(i % 2, i / 2));
    }
    return image;
}

std::filesystem::path temp_file(const std::string& name) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("glint_texture_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir / name;
}

void expect_rgb_near(const Rgb& a, const Rgb& b, double tolerance) {
    EXPECT_NEAR(a.r, b.r, tolerance) << a << " vs " << b;
    EXPECT_NEAR(a.g, b.g, tolerance) << a << " vs " << b;
    EXPECT_NEAR(a.b, b.b, tolerance) << a << " vs " << b;
}

TEST(ImageTexture, BilinearLookupOfAnExrFile) {
    const auto path = temp_file("tiny.exr");
    write_image(two_by_two(), path);
    const ImageTexture texture(read_image(path));
    // Texel centres: u = ¼, ¾; v = ¾ is the top row.
    expect_rgb_near(texture.lookup({0.25, 0.75}), {1, 0, 0}, 1e-7);
    expect_rgb_near(texture.lookup({0.75, 0.75}), {0, 1, 0}, 1e-7);
    expect_rgb_near(texture.lookup({0.25, 0.25}), {0, 0, 1}, 1e-7);
    expect_rgb_near(texture.lookup({0.75, 0.25}), {1, 1, 1}, 1e-7);
    // Between centres: weights by distance.
    expect_rgb_near(texture.lookup({0.375, 0.75}), {0.75, 0.25, 0}, 1e-7);
    expect_rgb_near(texture.lookup({0.5, 0.5}), {0.5, 0.5, 0.5}, 1e-7);
    // The image repeats: u = 0 lies halfway between the right column and the left one, u = 1.25 is ¼.
    expect_rgb_near(texture.lookup({0.0, 0.75}), {0.5, 0.5, 0}, 1e-7);
    expect_rgb_near(texture.lookup({1.25, -0.25}), {1, 0, 0}, 1e-7);
    EXPECT_EQ(texture.min_value(), 0.0);
    EXPECT_EQ(texture.max_value(), 1.0);
    std::filesystem::remove(path);
}

TEST(ImageTexture, EightBitFilesAreSrgbDecoded) {
    Image image(1, 1);
    image.rgb = {0.5f, 0.0f, 1.0f};  // written as sRGB bytes 188, 0, 255
    const auto path = temp_file("tiny.png");
    write_image(image, path);
    const ImageTexture texture(read_image(path));
    // 188 decodes to ((188/255 + 0.055)/1.055)^2.4 = 0.5029: linear again, to the byte's precision.
    expect_rgb_near(texture.lookup({0.3, 0.3}), {0.5029, 0, 1}, 1e-4);
    EXPECT_NEAR(srgb_to_linear(0.04045), 0.04045 / 12.92, 1e-15);  // the linear segment's end
    EXPECT_NEAR(srgb_to_linear(1.0), 1.0, 1e-15);
    std::filesystem::remove(path);
}

TEST(ImageTexture, SixteenBitGreyPgmTexture) {
    // A 2 × 1 binary PGM, maxval 65535, big-endian samples 65535 and 32768: white, and 32768/65535
    // sRGB-decoded, in all three channels. stb_image 2.27 used to hand back half the buffer glint then
    // read (the second texel came from past its end: a heap overflow under the sanitizers), and its
    // samples byte-swapped (32768 = 0x8000 would read as 128).
    const auto path = temp_file("grey16.pgm");
    std::ofstream(path, std::ios::binary) << std::string("P5\n2 1\n65535\n\xff\xff\x80\x00", 17);
    const ImageTexture texture(read_image(path));
    const double grey = std::pow((32768.0 / 65535 + 0.055) / 1.055, 2.4);  // ≈ 0.2140
    expect_rgb_near(texture.lookup({0.25, 0.5}), {1, 1, 1}, 1e-6);
    expect_rgb_near(texture.lookup({0.75, 0.5}), {grey, grey, grey}, 1e-6);
    expect_rgb_near(texture.lookup({0.5, 0.5}), {(1 + grey) / 2, (1 + grey) / 2, (1 + grey) / 2},
                    1e-6);  // halfway between the texel centres
    EXPECT_NEAR(texture.max_value(), 1.0, 1e-6);
    EXPECT_NEAR(texture.min_value(), grey, 1e-6);
    std::filesystem::remove(path);
}

TEST(ImageTexture, MissingOrUnreadableFilesAreErrors) {
    EXPECT_THROW(read_image(temp_file("does-not-exist.png")), std::runtime_error);
    const auto path = temp_file("not-an-image.png");
    std::ofstream(path) << "this is text";
    EXPECT_THROW(read_image(path), std::runtime_error);
    // A tiny file declaring a huge image: refused with the file's name and the limit, not allocated.
    std::ofstream(path, std::ios::binary) << "P5\n100000 100000\n255\n";
    try {
        read_image(path);
        ADD_FAILURE() << "read";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path.string() + ": PNM header declares 100000 x 100000 pixels"),
                  std::string::npos)
            << e.what();
    }
    std::filesystem::remove(path);
}

TEST(PerlinNoise, IsZeroOnTheLatticeBoundedAndDeterministic) {
    const PerlinNoise noise(7), same(7), other(8);
    double sum = 0, sum2 = 0, low = 0, high = 0;
    bool differs = false;
    const int n = 20000;
    for (std::uint32_t i = 0; i < n; ++i) {
        const SampleKey key{5, i, 0, 0};
        const Vec3 p{200 * key.uniform(0) - 100, 200 * key.uniform(1) - 100, 200 * key.uniform(2) - 100};
        const double v = noise.noise(p);
        EXPECT_EQ(v, same.noise(p));
        differs = differs || v != other.noise(p);
        low = std::min(low, v);
        high = std::max(high, v);
        sum += v;
        sum2 += v * v;
        // Gradient noise vanishes at integer points.
        EXPECT_NEAR(noise.noise({std::floor(p.x), std::floor(p.y), std::floor(p.z)}), 0.0, 1e-12);
        // Continuous: a tiny step changes it by a tiny amount.
        EXPECT_NEAR(noise.noise(p + Vec3{1e-7, 0, 0}), v, 1e-5);
    }
    EXPECT_TRUE(differs) << "the seed must change the pattern";
    EXPECT_GE(low, -1.0);
    EXPECT_LE(high, 1.0);
    EXPECT_NEAR(sum / n, 0.0, 0.02);      // no bias
    EXPECT_GT(std::sqrt(sum2 / n), 0.1);  // and not flat
    EXPECT_LT(high - low, 2.0);
    EXPECT_GT(high - low, 1.0);
}

TEST(NoiseTexture, BlendsBetweenItsTwoColours) {
    const Rgb a{0.1, 0.2, 0.3}, b{0.9, 0.5, 0.3};
    const NoiseTexture texture(3.0, 5, a, b);
    for (std::uint32_t i = 0; i < 2000; ++i) {
        const SampleKey key{6, i, 0, 0};
        const Rgb c = texture.evaluate(hit_at({key.uniform(0) * 10, key.uniform(1), key.uniform(2)}));
        const double t = (c.r - a.r) / (b.r - a.r);
        EXPECT_GE(t, 0.0);
        EXPECT_LE(t, 1.0);
        EXPECT_NEAR(c.g, a.g + t * (b.g - a.g), 1e-12);
        EXPECT_NEAR(c.b, 0.3, 1e-15);
    }
    EXPECT_NEAR(texture.min_value(), 0.1, 1e-15);
    EXPECT_NEAR(texture.max_value(), 0.9, 1e-15);
}

}  // namespace
}  // namespace glint
