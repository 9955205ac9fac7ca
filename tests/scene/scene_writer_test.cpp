// The YAML writer: parse → write → parse gives the same tree, and the same rendered bits.
#include "glint/scene/scene_writer.hpp"
#include "glint/scene/scene_set.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "test_data.hpp"

namespace glint {
namespace {

Node round_trip(const Node& root) {
    const std::string text = write_scene_yaml(root);
    return parse_scene_text(text, "<written>", ".").root;
}

TEST(SceneWriter, DefaultSceneRoundTripsToTheSameTree) {
    const SceneDesc desc = default_scene();
    const std::string text = write_scene_yaml(desc.root);
    const SceneDesc again = parse_scene_text(text, "<written>", ".");
    EXPECT_TRUE(same_tree(desc.root, again.root)) << text;
    // Writing is stable: the written text writes itself.
    EXPECT_EQ(write_scene_yaml(again.root), text);
}

TEST(SceneWriter, SmallValuesAreWrittenOnOneLineAndSectionsAsBlocks) {
    const std::string text = write_scene_yaml(default_scene().root);
    EXPECT_NE(text.find("  eye: [0, 1.6, 7]\n"), std::string::npos) << text;
    EXPECT_NE(text.find("  - {type: sphere, center: [0, 1, 0], radius: 1, material: red}\n"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find("render:\n  width: 640\n"), std::string::npos) << text;
}

TEST(SceneWriter, ScalarsThatYamlWouldReadDifferentlyAreQuoted) {
    // Each of these, written bare, would come back as something else (null, a list, a comment, a
    // map, trimmed text, another document…).
    const std::vector<std::string> awkward = {
        "",     "~",     "null",   "NULL",        "- a",         "-",
        "a: b", "a #b",  " lead",  "trail ",      "two  spaces", "[1, 2]",
        "{x}",  "'q'",   "\"dq\"", "back\\slash", "line\nbreak", "tab\there",
        "---",  "...",   "é ü",    "*alias",      "&anchor",     "!tag",
        "%x",   "@x",    "`x",     "|",           ">",           "x,y",
        "?",    "a - b", "0x1F",   "1e5",         "-1.5",        "yes"};
    Node root;
    root.kind = Node::Kind::Map;
    Node list;
    list.kind = Node::Kind::Sequence;
    for (const std::string& s : awkward) {
        Node scalar;
        scalar.kind = Node::Kind::Scalar;
        scalar.scalar = s;
        list.items.push_back(scalar);
        std::string key = "k";
        key.append(std::to_string(root.keys.size())).append(s);  // awkward keys too
        root.keys.push_back(key);
        root.items.push_back(scalar);
    }
    root.keys.push_back("list");
    root.items.push_back(list);
    const Node again = round_trip(root);
    ASSERT_TRUE(again.is_map());
    ASSERT_EQ(again.keys, root.keys) << write_scene_yaml(root);
    for (size_t i = 0; i < awkward.size(); ++i) {
        EXPECT_EQ(again.items[i].kind, Node::Kind::Scalar) << awkward[i];
        EXPECT_EQ(again.items[i].scalar, awkward[i]);
    }
    EXPECT_TRUE(same_tree(root, again)) << write_scene_yaml(root);
}

TEST(SceneWriter, NestedAndEmptyCollectionsRoundTrip) {
    const std::string text = R"(
a: {}
b: []
c: ~
d:
  - [1, [2, [3, [4]]]]
  - {x: {y: {z: {w: 1}}}}
  - - nested
    - list
  - {}
  - ~
e:
  deep: {one: [1, 2, 3], two: {three: 3}, long: [aaaaaaaaaaaaaaaaaaaa, bbbbbbbbbbbbbbbbbbbbbb, cccccccccccccccccccc, ddddddddddddddddddd, eeeeeeeeeeeeeeeeeee]}
)";
    const Node root = parse_scene_text(text, "<test>", ".").root;
    EXPECT_TRUE(same_tree(root, round_trip(root))) << write_scene_yaml(root);
}

TEST(SceneWriter, SameTreeNoticesAChange) {
    const Node a = default_scene().root;
    Node b = a;
    b.items[0].items[0].scalar = "641";
    EXPECT_FALSE(same_tree(a, b));
}

TEST(SceneWriter, WrittenSceneRendersTheSameBits) {
    const SceneDesc desc = default_scene();
    const SceneDesc again = parse_scene_text(write_scene_yaml(desc.root), "<written>", ".");
    RenderFlags small;
    small.width = 48;
    small.height = 27;
    small.samples_per_pixel = 4;
    const Scene a = build_scene(desc, small);
    const Scene b = build_scene(again, small);
    Film fa(48, 27), fb(48, 27);
    render(a, fa);
    render(b, fb);
    EXPECT_EQ(fa.to_image().rgb, fb.to_image().rgb);
}

TEST(SceneWriter, ExampleAndSharedScenesRoundTrip) {
    int count = 0;
    int folders = 0;
    for (const std::filesystem::path& folder :
         {std::filesystem::path(GLINT_SOURCE_DIR) / "examples", test::data_dir() / "scenes"}) {
        if (!std::filesystem::is_directory(folder)) {
            continue;
        }
        ++folders;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
            const auto ext = entry.path().extension();
            if (ext != ".yaml" && ext != ".yml" && ext != ".json") {
                continue;
            }
            const SceneDesc desc = load_scene_file(entry.path());
            EXPECT_TRUE(same_tree(desc.root, round_trip(desc.root))) << entry.path();
            ++count;
        }
    }
    if (folders == 0) {
        GTEST_SKIP() << "neither examples/ nor " << (test::data_dir() / "scenes").string() << " exists here";
    }
    EXPECT_GT(count, 0) << "no scene files found to round-trip";
}

}  // namespace
}  // namespace glint
