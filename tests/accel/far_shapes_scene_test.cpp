// Scenes whose shapes lie beyond float's range (the BVH's boxes are float) render at once. A floor of
// tiles, one reaching out to x = 1e40, made the accelerator's build recurse until the stack overflowed
// (the floor's box: infinite in x, flat in y, SAH area inf · 0 = NaN); spheres at 1e40 and of radius
// 1e300 made every SAH cost infinite, and all shapes one leaf. (Should the scene format come to reject
// such shapes, the error must say where, which this test accepts too.)
#include <gtest/gtest.h>

#include <chrono>

#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"

namespace glint {
namespace {

const char* const kHeader =
    "camera: {type: pinhole, eye: [0, 4, 5], look_at: [0, 0, -2], up: [0, 1, 0], fov: 60}\n"
    "materials: {grey: {type: matte, albedo: 0.5}}\n"
    "render: {width: 16, height: 16, samples: 2}\n"
    "lights: [{type: point, position: [0, 3, 3], intensity: 10}]\n"
    "objects:\n";

const char* const kFloor =
    "  - {type: rectangle, corner: [-2, -1, -3], edge1: [0, 0, 1], edge2: [1, 0, 0], material: grey}\n"
    "  - {type: rectangle, corner: [0, -1, -3], edge1: [0, 0, 1], edge2: [1, 0, 0], material: grey}\n"
    "  - {type: rectangle, corner: [2, -1, -3], edge1: [0, 0, 1], edge2: [1, 0, 0], material: grey}\n"
    "  - {type: rectangle, corner: [-2, -1, -1], edge1: [0, 0, 1], edge2: [1, 0, 0], material: grey}\n"
    "  - {type: rectangle, corner: [0, -1, -1], edge1: [0, 0, 1], edge2: [1, 0, 0], material: grey}\n"
    "  - {type: rectangle, corner: [2, -1, -1], edge1: [0, 0, 1], edge2: [1, 0, 0], material: grey}\n"
    "  - {type: rectangle, corner: [4, -1, -5], edge1: [0, 0, 1], edge2: [1e40, 0, 0], material: grey}\n";

const char* const kSpheres =
    "  - {type: sphere, center: [1e40, 0, 0], radius: 1, material: grey}\n"
    "  - {type: sphere, center: [0, 0, -50], radius: 1e300, material: grey}\n"
    "  - {type: sphere, center: [-1.5, 0, -2.5], radius: 0.5, material: grey}\n"
    "  - {type: rectangle, corner: [-1e40, -1, -3], edge1: [2e40, 0, 0], edge2: [0, 0, 0.5], material: "
    "grey}\n";

TEST(FarShapesScene, ShapesBeyondFloatRangeRenderWithinASecond) {
    for (const char* objects : {kFloor, kSpheres}) {
        for (const std::string accelerator : {"bvh", "list"}) {
            const auto start = std::chrono::steady_clock::now();
            try {
                RenderFlags overrides;
                overrides.accelerator = accelerator;
                const Scene scene =
                    build_scene(parse_scene_text(std::string(kHeader) + objects, "far.yaml", "."), overrides);
                // Straight down at (−1.5, ·, −2.5): the first tile of the floor, or the small sphere.
                Hit hit;
                ASSERT_TRUE(scene.world->intersect({{-1.5, 5, -2.5}, {0, -1, 0}}, kInf, hit)) << accelerator;
                EXPECT_DOUBLE_EQ(hit.t, objects == kFloor ? 6.0 : 4.5) << accelerator;
                Film film(scene.view.settings.width, scene.view.settings.height);
                render(scene, film);
            } catch (const SceneError& e) {
                EXPECT_EQ(e.position().file->path, "far.yaml") << e.what();
                EXPECT_GE(e.position().line, 6) << e.what();
            }
            EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0)
                << accelerator;
        }
    }
}

}  // namespace
}  // namespace glint
