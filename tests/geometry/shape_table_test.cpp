// The table of shapes against the documentation and the shapes example.
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

TEST(ShapeTable, EveryShapeIsDocumented) {
    const std::string doc = read_text(std::string(GLINT_SOURCE_DIR) + "/docs/scene-format.md");
    ASSERT_FALSE(doc.empty());
    for (const ShapeEntry& entry : shape_table()) {
        EXPECT_NE(doc.find("\n### " + entry.name + "\n"), std::string::npos)
            << entry.name << " is not documented";
    }
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

TEST(ShapeTable, TheTransformExampleInTheDocsBuilds) {
    const std::string doc = read_text(std::string(GLINT_SOURCE_DIR) + "/docs/scene-format.md");
    const size_t section = doc.find("\n### transform\n");
    ASSERT_NE(section, std::string::npos);
    const size_t begin = doc.find("```yaml\n", section);
    const size_t end = doc.find("```\n", begin + 8);
    ASSERT_NE(begin, std::string::npos);
    ASSERT_NE(end, std::string::npos);
    const std::string objects = doc.substr(begin + 8, end - begin - 8);
    EXPECT_EQ(testing::scene_error("materials: {blue: {type: matte}}\nobjects:\n" + objects), "") << objects;
}

}  // namespace
}  // namespace glint
