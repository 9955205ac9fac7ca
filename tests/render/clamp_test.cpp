// render.clamp, the firefly clamp: a sample brighter than the clamp is scaled down to it, hue kept.
#include <gtest/gtest.h>

#include "test_util.hpp"

namespace glint {
namespace {

TEST(FireflyClamp, ScalesABrightSampleDownToTheClampKeepingItsHue) {
    // The camera sees an emitter of radiance (10, 5, 0) fill the image: every sample is that radiance.
    const std::string scene =
        "camera: {eye: [0, 0, 5], look_at: [0, 0, 0], fov: 5}\n"
        "objects:\n  - {type: sphere, radius: 1, material: {type: emissive, radiance: [10, 5, 0]}}\n";
    const Film clamped = test::render_film(
        test::scene_from_text("render: {width: 4, height: 4, samples: 2, clamp: 2}\n" + scene));
    EXPECT_DOUBLE_EQ(clamped.pixel(2, 2).r, 2);
    EXPECT_DOUBLE_EQ(clamped.pixel(2, 2).g, 1);
    EXPECT_DOUBLE_EQ(clamped.pixel(2, 2).b, 0);
    const Film free =
        test::render_film(test::scene_from_text("render: {width: 4, height: 4, samples: 2}\n" + scene));
    EXPECT_DOUBLE_EQ(free.pixel(2, 2).r, 10);
    EXPECT_THROW(test::scene_from_text("render: {clamp: -1}\n" + scene), SceneError);
}

}  // namespace
}  // namespace glint
