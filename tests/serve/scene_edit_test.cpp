// Edits of the scene tree from the page: JSON values become scene text that reads back the same,
// paths are created or removed, and what is not allowed is refused with a reason.
#include "glint/serve/scene_edit.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_writer.hpp"
#include "glint/serve/preview_server.hpp"

namespace glint {
namespace {

using nlohmann::json;

TEST(SceneEdit, NumbersAreWrittenInTheShortestTextThatReadsBackTheSameDouble) {
    EXPECT_EQ(number_text(json(640)), "640");
    EXPECT_EQ(number_text(json(-3)), "-3");
    EXPECT_EQ(number_text(json(2.0)), "2");
    EXPECT_EQ(number_text(json(0.1)), "0.1");
    EXPECT_EQ(number_text(json(1.333)), "1.333");
    EXPECT_EQ(number_text(json(1e-7)), "1e-07");
    for (const double x : {0.1, 1.0 / 3.0, 2.417, 1e-300, 6.02214076e23, -0.8}) {
        EXPECT_EQ(std::strtod(number_text(json(x)).c_str(), nullptr), x) << x;
    }
}

TEST(SceneEdit, TreeToJsonKeepsOrderAndTypes) {
    const Node root = parse_scene_text("b: 1\na: [1.5, x, true]\nc: ~\nd: '7'\n", "<t>", ".").root;
    const auto j = node_to_json(root);
    EXPECT_EQ(j.dump(), R"({"b":1,"a":[1.5,"x",true],"c":null,"d":7})");
}

TEST(SceneEdit, EditsSetCreateAndRemoveKeys) {
    Node root = default_scene().root;
    apply_edits(root, parse_edits(json::parse(R"({"edits": [
        {"path": ["camera", "fov"], "value": 20},
        {"path": ["camera", "lens_radius"], "value": 0.05},
        {"path": ["materials", "red", "roughness"], "value": 0.3},
        {"path": ["render", "sampler"], "value": "random"},
        {"path": ["background"], "value": [0, 0, 0]},
        {"path": ["camera", "up"], "value": null},
        {"path": ["render", "nothing", "here"], "value": null}]})")));
    const Node again = parse_scene_text(write_scene_yaml(root), "<t>", ".").root;
    EXPECT_EQ(again.find("camera")->find("fov")->scalar, "20");
    EXPECT_EQ(again.find("camera")->find("lens_radius")->scalar, "0.05");
    EXPECT_EQ(again.find("camera")->find("up"), nullptr);
    EXPECT_EQ(again.find("materials")->find("red")->find("roughness")->scalar, "0.3");
    EXPECT_EQ(again.find("render")->find("sampler")->scalar, "random");
    EXPECT_EQ(again.find("render")->find("nothing"), nullptr);
    EXPECT_EQ(again.find("background")->items.size(), 3u);
}

TEST(SceneEdit, MissingSectionsAreCreated) {
    Node root = parse_scene_text("objects: []\n", "<t>", ".").root;
    apply_edits(root, parse_edits(json::parse(R"({"path": ["render", "width"], "value": 32})")));
    EXPECT_EQ(root.find("render")->find("width")->scalar, "32");
}

TEST(SceneEdit, RefusesWhatCouldReadFilesOrIsNotAValue) {
    const auto refused = [](const char* text) {
        try {
            parse_edits(json::parse(text));
        } catch (const EditError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(refused(R"({"path": ["objects"], "value": 1})"), "");
    EXPECT_NE(refused(R"({"path": ["lights", "x"], "value": 1})"), "");
    EXPECT_NE(refused(R"({"path": ["materials", "m", "texture"], "value": "wood.png"})").find("one word"),
              std::string::npos);
    EXPECT_NE(refused(R"({"path": ["materials", "m", "file"], "value": "/etc/passwd"})"), "");
    EXPECT_NE(refused(R"({"path": ["camera", "../x"], "value": 1})"), "");
    EXPECT_NE(refused(R"({"path": ["camera", "eye"], "value": [[1, 2]]})"), "");
    EXPECT_NE(refused(R"({"path": [], "value": 1})"), "");
    EXPECT_NE(refused(R"({"path": ["camera", "x"]})"), "");
    EXPECT_NE(refused(R"("just text")"), "");
    EXPECT_EQ(refused(R"({"path": ["camera", "type"], "value": "thin_lens"})"), "");
}

TEST(SceneEdit, AKeyUnderAScalarIsRefused) {
    Node root = default_scene().root;
    EXPECT_THROW(
        apply_edits(root, parse_edits(json::parse(R"({"path": ["camera", "fov", "x"], "value": 1})"))),
        EditError);
}

TEST(ServeCommand, ABadSceneExitsWithTwoAndAMessage) {
    const std::string command =
        std::string(GLINT_CLI_PATH) + " serve /nonexistent/scene.yaml --port 0 2>/dev/null";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 2);
}

TEST(ServeCommand, APortInUseExitsWithOneAndAMessage) {
    PreviewServer holder(default_scene(), "holder");
    const int port = holder.bind("127.0.0.1", 0);
    const std::string command =
        std::string(GLINT_CLI_PATH) + " serve --port " + std::to_string(port) + " 2>/dev/null >/dev/null";
    const int status = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 1);
}

}  // namespace
}  // namespace glint
