// Morgan McGuire's OBJ + MTL Cornell box (examples/assets/cornell-box-obj, public domain; credits in
// examples/assets/CREDITS.md), imported as a user would: its parts, its materials from the MTL, its
// light, and a render that the light reaches.
#include <gtest/gtest.h>

#include "glint/geometry/mesh.hpp"
#include "glint/import/importer.hpp"
#include "glint/scene/scene_writer.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

const std::filesystem::path kBox =
    std::filesystem::path(GLINT_SOURCE_DIR) / "examples/assets/cornell-box-obj/CornellBox-Original.obj";

const Node& object_named(const SceneDesc& desc, const std::string& material) {
    for (const Node& object : desc.root.find("objects")->items) {
        if (object.find("obj_material") && object.find("obj_material")->scalar == material) {
            return object;
        }
    }
    throw std::runtime_error("no object for " + material);
}

TEST(ObjSampleModels, McGuiresCornellBoxImportsAsItsAuthorsMeantIt) {
    const SceneDesc desc = load_scene(kBox);
    // One object per material, in the order the file uses them: 18 quads, 36 triangles in all.
    ASSERT_EQ(desc.root.find("objects")->items.size(), 8u);
    EXPECT_EQ(write_scene_yaml(*object_named(desc, "leftWall").find("material")),
              "type: matte\n\nalbedo: [0.63, 0.065, 0.05]\n");
    EXPECT_EQ(write_scene_yaml(*object_named(desc, "light").find("material")),
              "type: emissive\n\nradiance: [17, 12, 4]\n");
    EXPECT_EQ(desc.root.find("lights"), nullptr);  // the box has its own light: no sky is added
    const Scene scene = build_scene(desc);
    std::size_t triangles = 0;
    for (const auto& shape : scene.world->shapes) {
        const auto* mesh = dynamic_cast<const Mesh*>(shape.get());
        ASSERT_NE(mesh, nullptr);
        triangles += mesh->triangles().size();
    }
    EXPECT_EQ(triangles, 36u);
    ASSERT_EQ(scene.world->lights.size(), 1u);  // the emissive quad became the area light
}

TEST(ObjSampleModels, TheLightIsSeenAndLightsTheBox) {
    RenderFlags flags;
    flags.width = 16;
    flags.height = 16;
    flags.samples_per_pixel = 16;
    SceneDesc desc = load_scene(kBox);
    apply_set(desc, "camera.eye=[0, 1, 3.9]");
    const Film film = test::render_film(build_scene(desc, flags));
    // The light, seen from the front, covers part of a pixel near the top middle: that pixel's red is
    // a good share of its radiance's 17 and more than any lit wall's.
    double brightest = 0;
    for (int x = 0; x < 16; ++x) {
        for (int y = 0; y < 4; ++y) {
            brightest = std::max(brightest, film.pixel(x, y).r);
        }
    }
    EXPECT_GT(brightest, 5);
    EXPECT_LT(brightest, 17);
    // The middle of the image (the back wall and the tall box, white) is lit, warm as the light.
    const Rgb middle = film.pixel(8, 8);
    EXPECT_GT(middle.r, 0.05);
    EXPECT_GT(middle.r, middle.b);
}

}  // namespace
}  // namespace glint
