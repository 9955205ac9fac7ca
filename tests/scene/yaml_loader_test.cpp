// The YAML reader (scene/yaml_loader.cpp): what a scene's text becomes as glint::Node, and where its
// messages point. Positions are 1-based bytes of the line, whatever characters come before.
#include <gtest/gtest.h>

#include <string>

#include "glint/scene/scene_desc.hpp"

namespace glint {
namespace {

SceneError parse_error(const std::string& text) {
    try {
        parse_scene_text(text, "x.yaml", ".");
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return SceneError({}, "");
}

// The 1-based column of the first `word` on line `line` (1-based) of `text`, found in the text itself.
int column_of(const std::string& text, int line, const std::string& word) {
    std::size_t start = 0;
    for (int l = 1; l < line; ++l) {
        start = text.find('\n', start) + 1;
    }
    return static_cast<int>(text.find(word, start) - start) + 1;
}

TEST(YamlLoader, NullsAreUnquotedUntaggedNullWords) {
    const SceneDesc desc = parse_scene_text(
        "a: ~\nb: null\nc: Null\nd: NULL\ne:\nf: 'null'\ng: \"~\"\nh: nil\ni: nulls\n", "x.yaml", ".");
    const Node& root = desc.root;
    for (const char* key : {"a", "b", "c", "d", "e"}) {
        EXPECT_EQ(root.find(key)->kind, Node::Kind::Null) << key;
    }
    for (const auto& [key, text] : {std::pair{"f", "null"}, {"g", "~"}, {"h", "nil"}, {"i", "nulls"}}) {
        ASSERT_EQ(root.find(key)->kind, Node::Kind::Scalar) << key;
        EXPECT_EQ(root.find(key)->scalar, text);
    }
}

TEST(YamlLoader, ValuesKeysAndPositionsOfBlockAndFlowStyle) {
    const std::string text =
        "render:\n  width: 64\nobjects:\n  - {type: sphere, radius: 2.5}\n  - [1, 'two']\n";
    const SceneDesc desc = parse_scene_text(text, "x.yaml", ".");
    const Node& objects = *desc.root.find("objects");
    ASSERT_TRUE(objects.is_sequence());
    ASSERT_EQ(objects.items.size(), 2u);
    const Node& sphere = objects.items[0];
    ASSERT_TRUE(sphere.is_map());
    EXPECT_EQ(sphere.keys, (std::vector<std::string>{"type", "radius"}));
    EXPECT_EQ(sphere.find("radius")->scalar, "2.5");
    EXPECT_EQ(sphere.pos.line, 4);
    EXPECT_EQ(sphere.pos.column, column_of(text, 4, "{"));
    EXPECT_EQ(sphere.key_positions[1].column, column_of(text, 4, "radius"));
    EXPECT_EQ(sphere.find("radius")->pos.column, column_of(text, 4, "2.5"));
    EXPECT_EQ(objects.items[1].items[1].scalar, "two");
    EXPECT_EQ(desc.root.find("render")->find("width")->pos.line, 2);
}

TEST(YamlLoader, JsonIsRead) {
    const SceneDesc desc =
        parse_scene_text(R"({"objects":[{"type":"sphere","radius":1}],"a":null})", "x.json", ".");
    EXPECT_EQ(desc.root.find("objects")->items[0].find("type")->scalar, "sphere");
    EXPECT_EQ(desc.root.find("a")->kind, Node::Kind::Null);
}

TEST(YamlLoader, ColumnsCountBytesAfterNonAsciiCharacters) {
    // Two two-byte characters before the key: its byte column is two more than its character column.
    const std::string text =
        "# \xC3\xA9t\xC3\xA9\nobjects:\n  - {name: \"\xC3\xA9\xE2\x80\x94\", radious: 1}\n";
    const SceneDesc desc = parse_scene_text(text, "x.yaml", ".");
    const Node& object = desc.root.find("objects")->items[0];
    EXPECT_EQ(object.key_positions[1].line, 3);
    EXPECT_EQ(object.key_positions[1].column, column_of(text, 3, "radious"));
    EXPECT_EQ(object.find("radious")->pos.column, column_of(text, 3, "1}"));
}

TEST(YamlLoader, EveryLineOfNonAsciiTextCountsItsOwnBytes) {
    // The loader finds each line's first byte once and measures the line's marks from it: marks on the
    // same line after several characters of two and three bytes, then lines whose characters differ,
    // then a line whose first mark follows multi-byte characters.
    const std::string text =
        "a: [\"\xE2\x80\x94\xE2\x80\x94\", 1, \"\xC3\xA9\", 2]\n"
        "b: {x: \"\xC3\xA9\xC3\xA9\xC3\xA9\", y: 3, z: 4}\n"
        "c: [5, \"\xE2\x80\x94\", 6]\n"
        // A quoted scalar that goes on to the next line: that line's first marks follow two
        // three-byte characters, so its start is found by walking back over them.
        "d: [\"\xC3\xA9\n  \xE2\x80\x94\xE2\x80\x94\", 7]\n";
    const SceneDesc desc = parse_scene_text(text, "x.yaml", ".");
    const Node& a = *desc.root.find("a");
    EXPECT_EQ(a.items[1].pos.column, column_of(text, 1, "1,"));
    EXPECT_EQ(a.items[3].pos.column, column_of(text, 1, "2]"));
    const Node& b = *desc.root.find("b");
    EXPECT_EQ(b.key_positions[1].line, 2);
    EXPECT_EQ(b.key_positions[1].column, column_of(text, 2, "y:"));
    EXPECT_EQ(b.key_positions[2].column, column_of(text, 2, "z:"));
    EXPECT_EQ(b.find("z")->pos.column, column_of(text, 2, "4}"));
    const Node& c = *desc.root.find("c");
    EXPECT_EQ(c.items[0].pos.line, 3);
    EXPECT_EQ(c.items[0].pos.column, column_of(text, 3, "5,"));
    EXPECT_EQ(c.items[2].pos.column, column_of(text, 3, "6]"));
    const Node& d = *desc.root.find("d");
    EXPECT_EQ(d.items[1].pos.line, 5);
    EXPECT_EQ(d.items[1].pos.column, column_of(text, 5, "7]"));
}

TEST(YamlLoader, AByteOrderMarkIsPartOfTheFirstLinesColumns) {
    const std::string text =
        "\xEF\xBB\xBF"
        "a: [1, 2]\nb: 3\n";
    const SceneDesc desc = parse_scene_text(text, "x.yaml", ".");
    EXPECT_EQ(desc.root.find("a")->pos.column, column_of(text, 1, "["));
    EXPECT_EQ(desc.root.find("b")->pos.column, 4);
}

TEST(YamlLoader, SyntaxErrorsPointWhereTheTextStopsMakingSense) {
    const std::string text = "a: 1\nb: [1, 2\nc: 3\n";
    const SceneError e = parse_error(text);
    EXPECT_EQ(e.message().rfind("syntax error: ", 0), 0u) << e.what();
    EXPECT_GE(e.position().line, 2) << e.what();
}

TEST(YamlLoader, TextThatIsNotUtf8IsRefusedAtItsByte) {
    const SceneError e = parse_error("a: b\nc: d\xFF\n");
    EXPECT_NE(e.message().find("not UTF-8"), std::string::npos) << e.what();
    EXPECT_EQ(e.position().line, 2) << e.what();
    EXPECT_EQ(e.position().column, 5) << e.what();
}

TEST(YamlLoader, AnAliasWithoutItsAnchorIsAnError) {
    const std::string text = "a: 1\nb: *nowhere\n";
    const SceneError e = parse_error(text);
    EXPECT_NE(e.message().find("unknown alias *nowhere"), std::string::npos) << e.what();
    EXPECT_EQ(e.position().line, 2);
    EXPECT_EQ(e.position().column, column_of(text, 2, "*"));
}

TEST(YamlLoader, AnAliasIsACopyOfItsValueWithItsPositions) {
    const std::string text = "a: &x {b: [1, 2]}\nc: *x\n";
    const SceneDesc desc = parse_scene_text(text, "x.yaml", ".");
    const Node& copy = *desc.root.find("c");
    ASSERT_TRUE(copy.is_map());
    EXPECT_EQ(copy.find("b")->items[1].scalar, "2");
    EXPECT_EQ(copy.pos.line, 1);  // where the value is written, as the anchor's
}

TEST(YamlLoader, KeysMustBeWordsAndUnique) {
    EXPECT_NE(parse_error("[a]: 1\n").message().find("a key must be a plain word"), std::string::npos);
    EXPECT_NE(parse_error("? ~\n: 1\n").message().find("a key must be a plain word"), std::string::npos);
    const std::string text = "a: 1\nb: 2\na: 3\n";
    const SceneError e = parse_error(text);
    EXPECT_NE(e.message().find("duplicate key 'a'"), std::string::npos) << e.what();
    EXPECT_EQ(e.position().line, 3);
}

TEST(YamlLoader, OnlyTheFirstDocumentIsRead) {
    const SceneDesc desc = parse_scene_text("a: 1\n---\nb: [unclosed\n", "x.yaml", ".");
    EXPECT_TRUE(desc.root.find("a"));
    EXPECT_FALSE(desc.root.find("b"));
}

}  // namespace
}  // namespace glint
