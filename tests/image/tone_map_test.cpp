// Exposure and tone curves (src/glint/image/tone_map.cpp) against their formulas at values worked out
// by hand, and the promise that only 8-bit output is tone mapped: EXR and PFM hold the film as it is.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "glint/image/image_io.hpp"
#include "glint/image/tone_map.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

TEST(ToneMap, CurvesMatchTheirFormulas) {
    EXPECT_EQ(tone_curve(ToneCurve::Clamp, 0.25), 0.25);
    EXPECT_EQ(tone_curve(ToneCurve::Clamp, 2.0), 1.0);
    EXPECT_EQ(tone_curve(ToneCurve::Reinhard, 1.0), 0.5);   // 1 / (1 + 1)
    EXPECT_EQ(tone_curve(ToneCurve::Reinhard, 3.0), 0.75);  // 3 / (1 + 3)
    // Narkowicz's fit at 1: (2.51 + 0.03) / (2.43 + 0.59 + 0.14) = 2.54 / 3.16.
    EXPECT_NEAR(tone_curve(ToneCurve::Aces, 1.0), 2.54 / 3.16, 1e-15);
    // At 0.18 (middle grey): 0.18 (2.51 · 0.18 + 0.03) / (0.18 (2.43 · 0.18 + 0.59) + 0.14).
    EXPECT_NEAR(tone_curve(ToneCurve::Aces, 0.18), 0.18 * 0.4818 / (0.18 * 1.0274 + 0.14), 1e-15);
    EXPECT_EQ(tone_curve(ToneCurve::Aces, 100.0), 1.0);
    for (ToneCurve curve : {ToneCurve::Clamp, ToneCurve::Reinhard, ToneCurve::Aces, ToneCurve::Agx}) {
        EXPECT_EQ(tone_curve(curve, -1.0), 0.0);
        EXPECT_EQ(tone_curve(curve, std::numeric_limits<double>::quiet_NaN()), 0.0);
        // AgX tops out at 0.997 (its polynomial reaches 0.9986 at the top of its range).
        EXPECT_NEAR(tone_curve(curve, std::numeric_limits<double>::infinity()), 1.0,
                    curve == ToneCurve::Agx ? 0.01 : 0.0);
        // Monotone: a brighter pixel never comes out darker.
        double previous = 0;
        for (double x = 0; x < 20; x += 0.01) {
            const double y = tone_curve(curve, x);
            EXPECT_GE(y, previous) << x;
            previous = y;
        }
    }
}

// AgX (Wrensch's minimal form of Sobotka's curve) on grey: the inset matrix's rows sum to 1 within 1.4e-4
// and the outset undoes it, so grey x is the polynomial at x's place in the 16.5 stops, to the power 2.2.
double agx_on_grey_by_hand(double x) {
    const double t = (std::log2(x) + 12.47393) / (4.026069 + 12.47393);
    const double p = 15.5 * std::pow(t, 6) - 40.14 * std::pow(t, 5) + 31.96 * std::pow(t, 4) -
                     6.868 * std::pow(t, 3) + 0.4298 * t * t + 0.1191 * t - 0.00232;
    return std::pow(p, 2.2);
}

TEST(ToneMap, AgxFollowsWrenschsFitOnGreyAndDesaturatesBrightColours) {
    // Middle grey sits at 0.606 of the range: 0.4967 encoded, 0.2145 linear.
    EXPECT_NEAR(tone_curve(ToneCurve::Agx, 0.18), 0.21452, 1e-3);
    for (double x : {0.01, 0.18, 1.0, 4.0}) {
        EXPECT_NEAR(tone_curve(ToneCurve::Agx, x), agx_on_grey_by_hand(x), 1e-3) << x;
        const Rgb grey = tone_map_pixel(ToneCurve::Agx, Rgb(x));
        EXPECT_NEAR(grey.r, grey.g, 1e-3) << x;  // grey stays grey
        EXPECT_NEAR(grey.b, grey.g, 1e-3) << x;
    }
    EXPECT_NEAR(tone_curve(ToneCurve::Agx, 1e6), 1.0, 0.01);  // the top of the 16.5 stops: white
    EXPECT_LT(tone_curve(ToneCurve::Agx, 1e-6), 1e-3);
    // A very bright pure red goes towards white: its green and blue rise well above zero, where the
    // per-channel curves keep them at 0.
    const Rgb red = tone_map_pixel(ToneCurve::Agx, Rgb(1000, 0, 0));
    EXPECT_GT(red.r, 0.9);
    EXPECT_GT(red.g, 0.2);
    EXPECT_GT(red.b, 0.2);
    EXPECT_EQ(tone_map_pixel(ToneCurve::Aces, Rgb(1000, 0, 0)).g, 0.0);
    // A dim pure red stays red.
    const Rgb dim_red = tone_map_pixel(ToneCurve::Agx, Rgb(0.2, 0, 0));
    EXPECT_GT(dim_red.r, 5 * dim_red.g);
    // NaN and negative channels carry no light; every output is in [0, 1].
    const Rgb odd = tone_map_pixel(ToneCurve::Agx, Rgb(std::numeric_limits<double>::quiet_NaN(), -3,
                                                       std::numeric_limits<double>::infinity()));
    for (double v : {odd.r, odd.g, odd.b}) {
        EXPECT_GE(v, 0.0);
        EXPECT_LE(v, 1.0);
    }
}

TEST(ToneMap, ExposureScalesByTwoToTheStopsBeforeTheCurve) {
    Image image(1, 1);
    image.rgb = {0.5f, 1.5f, 0.25f};
    const Image brighter = to_display(image, {1, ToneCurve::Reinhard});
    EXPECT_FLOAT_EQ(brighter.rgb[0], 0.5f);   // 1 / (1 + 1)
    EXPECT_FLOAT_EQ(brighter.rgb[1], 0.75f);  // 3 / (1 + 3)
    const Image darker = to_display(image, {-2, ToneCurve::Clamp});
    EXPECT_FLOAT_EQ(darker.rgb[1], 0.375f);
}

std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(ToneMap, OnlyPngOutputIsToneMapped) {
    test::TempDir dir;
    dir.write("s.yaml",
              "render: {width: 8, height: 8, samples: 1}\nobjects:\n  - {type: sphere, radius: 1}\n"
              "lights:\n  - {type: point, position: [0, 0, 5], intensity: 100}\n");
    const std::string scene = "render '" + (dir / "s.yaml").string() + "' -q -o '";
    for (const char* extension : {"pfm", "exr", "png"}) {
        ASSERT_EQ(test::run_glint(scene + (dir / "plain.").string() + extension + "'").exit_code, 0);
        ASSERT_EQ(
            test::run_glint(scene + (dir / "mapped.").string() + extension + "' --tonemap aces --exposure -1")
                .exit_code,
            0);
        const bool same = read_file(dir / (std::string("plain.") + extension)) ==
                          read_file(dir / (std::string("mapped.") + extension));
        EXPECT_EQ(same, std::string(extension) != "png") << extension;
    }
    const auto bad = test::run_glint(scene + (dir / "x.png").string() + "' --exposure 100");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.output.find("from -64 to 64"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace glint
