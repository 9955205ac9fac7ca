// The table of shapes against the shapes example (tests/docs holds it against docs/scene-format.md).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "geometry/shape_testing.hpp"
#include "glint/scene/scene.hpp"

namespace glint {
namespace {

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

TEST(ShapeTable, TheShapesExampleBuildsAndUsesEveryShape) {
    const std::string path = std::string(GLINT_SOURCE_DIR) + "/examples/shapes.yaml";
    const Scene scene = build_scene(load_scene_file(path));
    const std::string text = read_text(path);
    for (const ShapeEntry& entry : shape_table()) {
        EXPECT_NE(text.find("type: " + entry.name), std::string::npos)
            << entry.name << " is not in shapes.yaml";
    }
    EXPECT_NE(text.find("transform:"), std::string::npos);
    EXPECT_GE(scene.world->shapes.size(), shape_table().size());
}

}  // namespace
}  // namespace glint
