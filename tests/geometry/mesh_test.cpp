// {type: mesh} in a scene: the file is found relative to the scene, and a bad file is an error that
// points into the mesh file (or at the scene's `file:` when the file is missing).
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>

#include "glint/geometry/mesh.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"

namespace glint {
namespace {

std::string scene_with_mesh(const std::string& file) {
    return "camera: {type: pinhole, eye: [0, 0, 5], look_at: [0, 0, 0], up: [0, 1, 0], fov: 40}\n"
           "materials: {grey: {type: matte, albedo: 0.5}}\n"
           "objects:\n"
           "  - {type: mesh, file: " +
           file + ", material: grey}\n";
}

std::filesystem::path scene_dir() {
    const auto dir = std::filesystem::path(testing::TempDir()) / "mesh_scene";
    std::filesystem::create_directories(dir / "models");
    return dir;
}

TEST(MeshShape, FileIsFoundRelativeToTheSceneAndRenders) {
    const auto dir = scene_dir();
    std::ofstream(dir / "models" / "tri.obj") << "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n";
    for (const std::string accel : {"bvh", "list"}) {
        RenderFlags overrides;
        overrides.accelerator = accel;
        const Scene scene =
            build_scene(parse_scene_text(scene_with_mesh("models/tri.obj"), "s.yaml", dir), overrides);
        ASSERT_EQ(scene.world->shapes.size(), 1u);
        ASSERT_NE(dynamic_cast<const Mesh*>(scene.world->shapes[0].get()), nullptr);
        Hit hit;
        ASSERT_TRUE(scene.world->intersect({{0, 0, 5}, {0, 0, -1}}, kInf, hit));
        EXPECT_DOUBLE_EQ(hit.t, 5);
        EXPECT_NEAR(hit.normal.z, 1, 1e-15);  // counter-clockwise seen from +z
        EXPECT_FALSE(scene.world->intersect({{0.9, 0.9, 5}, {0, 0, -1}}, kInf, hit));
    }
}

TEST(MeshShape, MissingOrBadFilesArePositionedErrors) {
    const auto dir = scene_dir();
    try {
        build_scene(parse_scene_text(scene_with_mesh("models/none.obj"), "s.yaml", dir));
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.position().file->path, "s.yaml");
        EXPECT_EQ(e.position().line, 4);
        EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
    }
    std::ofstream(dir / "models" / "bad.obj") << "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 x\n";
    try {
        build_scene(parse_scene_text(scene_with_mesh("models/bad.obj"), "s.yaml", dir));
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.position().file->path, (dir / "models" / "bad.obj").string());
        EXPECT_EQ(e.position().line, 4);
        EXPECT_EQ(e.position().column, 7);
    }
    // Only degenerate triangles: an error at the scene's `file:`, not an empty shape.
    std::ofstream(dir / "models" / "flat.obj") << "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n";
    try {
        build_scene(parse_scene_text(scene_with_mesh("models/flat.obj"), "s.yaml", dir));
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.position().file->path, "s.yaml");
        EXPECT_NE(std::string(e.what()).find("non-zero area"), std::string::npos) << e.what();
    }
}

// A mesh file with a coordinate float cannot hold (the BVH's boxes are float): an error in the mesh
// file at the number, within a second (such a vertex once made the BVH build recurse for ever).
TEST(MeshShape, AVertexBeyondFloatRangeIsAnErrorAtItsNumber) {
    const auto dir = scene_dir();
    std::ofstream(dir / "models" / "far.obj") << "v -1 -1 0\nv 1 -1 0\nv 0 1 1e40\nf 1 2 3\n";
    const auto start = std::chrono::steady_clock::now();
    try {
        build_scene(parse_scene_text(scene_with_mesh("models/far.obj"), "s.yaml", dir));
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.position().file->path, (dir / "models" / "far.obj").string());
        EXPECT_EQ(e.position().line, 3);
        EXPECT_EQ(e.position().column, 7);
        EXPECT_NE(std::string(e.what()).find("beyond float's range"), std::string::npos) << e.what();
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
}

}  // namespace
}  // namespace glint
