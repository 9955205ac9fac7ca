#include "glint/image/film.hpp"

#include <gtest/gtest.h>

namespace glint {
namespace {

TEST(Film, PaperSection21AveragingExample) {
    // 25 samples in one pixel: 16 yellow and 9 grey average to (0.82, 0.82, 0.18) (paper §2.1).
    Film film(1, 1);
    for (int i = 0; i < 16; ++i) {
        film.add_sample(0, 0, {1, 1, 0});
    }
    for (int i = 0; i < 9; ++i) {
        film.add_sample(0, 0, Rgb(0.5));
    }
    const Rgb c = film.pixel(0, 0);
    EXPECT_NEAR(c.r, 0.82, 1e-15);
    EXPECT_NEAR(c.g, 0.82, 1e-15);
    EXPECT_NEAR(c.b, 0.18, 1e-15);
    EXPECT_EQ(film.sample_count(0, 0), 25u);
}

TEST(Film, ToImageKeepsPixelsInPlace) {
    Film film(3, 2);
    film.add_sample(2, 1, {0.25, 0.5, 2.0});
    const Image image = film.to_image();
    EXPECT_EQ(image.pixel(2, 1)[0], 0.25f);
    EXPECT_EQ(image.pixel(2, 1)[2], 2.0f);  // linear radiance is not clamped in the film
    EXPECT_EQ(image.pixel(0, 0)[0], 0.0f);
}

}  // namespace
}  // namespace glint
