// render.crop and `glint render --crop`: the window is rendered alone and is bit for bit that part of
// the full render, whatever the threads and tiles.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "glint/image/image_io.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

const char* kScene =
    "render: {width: 40, height: 30, samples: 8, integrator: path, max_depth: 4}\n"
    "camera: {eye: [0, 1, 5], look_at: [0, 0.5, 0]}\n"
    "objects:\n  - {type: sphere, center: [0, 1, 0], radius: 1, material: {type: dielectric, ior: 1.5}}\n"
    "  - {type: plane, normal: [0, 1, 0]}\n"
    "lights:\n  - {type: environment, radiance: [0.5, 0.7, 1.0]}\n";

TEST(Crop, TheWindowIsThatPartOfTheFullRenderBitForBit) {
    test::TempDir dir;
    dir.write("s.yaml", kScene);
    const std::string render = "render '" + (dir / "s.yaml").string() + "' -q ";
    ASSERT_EQ(test::run_glint(render + "-o '" + (dir / "full.pfm").string() + "'").exit_code, 0);
    ASSERT_EQ(
        test::run_glint(render + "--crop 7,5,33,21 --threads 1 -o '" + (dir / "crop.pfm").string() + "'")
            .exit_code,
        0);
    const Image full = read_image(dir / "full.pfm");
    const Image crop = read_image(dir / "crop.pfm");
    ASSERT_EQ(crop.width, 26);
    ASSERT_EQ(crop.height, 16);
    for (int y = 0; y < crop.height; ++y) {
        ASSERT_EQ(std::memcmp(crop.pixel(0, y), full.pixel(7, 5 + y), sizeof(float) * 3 * 26), 0)
            << "row " << y;
    }
}

TEST(Crop, AWindowOutsideTheImageIsAPositionedError) {
    EXPECT_THROW(test::scene_from_text(std::string(kScene) + "",
                                       [] {
                                           RenderFlags flags;
                                           flags.crop = "0,0,41,30";
                                           return flags;
                                       }()),
                 SceneError);
    EXPECT_THROW(test::scene_from_text("render: {crop: [5, 5, 5, 9]}\n"), SceneError);
    EXPECT_THROW(test::scene_from_text("render: {crop: [0, 0, 4]}\n"), SceneError);
}

}  // namespace
}  // namespace glint
