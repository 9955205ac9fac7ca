// Where the glTF importer's messages point (import/json_positions.cpp, import/gltf_positions.cpp):
// every warning at the element it is about, in a .gltf written here by hand, and in the JSON chunk of
// a .glb; malformed JSON and tinygltf's own reasons at their line and column. The expected positions
// are found by searching the text for the key, not by the code under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <string_view>

#include "glint/import/importer.hpp"
#include "glint/import/json_positions.hpp"
#include "gltf_test_util.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

struct LineColumn {
    int line = 0;
    int column = 0;
};

// The 1-based line and column of the first byte of the `occurrence`-th `needle` in `text`.
LineColumn position_of(std::string_view text, std::string_view needle, int occurrence = 0) {
    std::size_t at = text.find(needle);
    for (int i = 0; i < occurrence && at != std::string_view::npos; ++i) {
        at = text.find(needle, at + 1);
    }
    EXPECT_NE(at, std::string_view::npos) << needle;
    if (at == std::string_view::npos) {
        return {};
    }
    const std::string_view before = text.substr(0, at);
    const std::size_t line_start = before.rfind('\n') == std::string_view::npos ? 0 : before.rfind('\n') + 1;
    return {1 + static_cast<int>(std::count(before.begin(), before.end(), '\n')),
            1 + static_cast<int>(at - line_start)};
}

void expect_at(const SourcePos& pos, LineColumn expected, const std::string& what) {
    EXPECT_EQ(pos.line, expected.line) << what;
    EXPECT_EQ(pos.column, expected.column) << what;
}

TEST(JsonPositions, KeysElementsAndTheirNearestAncestor) {
    // Numbers end where the parser reads one byte past them; keys hold an escaped quote and a '/'.
    const std::string text =
        "{\n"
        "  \"list\": [10 , 2.5,\n"
        "    {\"inner\": true}, [7, 8]],\n"
        "  \"a/b\": null,\n"
        "\t\"q\\\"uote\":\"x\" ,\"last\":-1e3}";
    const auto source = SourceFile::from_text("t.json", text);
    const JsonPositions positions(source, {});
    expect_at(positions.at(""), {1, 1}, "the root");
    expect_at(positions.at("/list"), position_of(text, "\"list\""), "a key");
    expect_at(positions.at("/list/0"), position_of(text, "10"), "a top-level array's number");
    expect_at(positions.at("/list/1"), position_of(text, "2.5"), "after a number and a space");
    expect_at(positions.at("/list/2"), position_of(text, "{\"inner\""), "an object in an array");
    expect_at(positions.at("/list/2/inner"), position_of(text, "\"inner\""), "its key");
    expect_at(positions.at("/list/3"), position_of(text, "[7"), "an array in an array");
    // Numbers inside an array below the top level are kept at their array.
    EXPECT_FALSE(positions.contains("/list/3/1"));
    expect_at(positions.at("/list/3/1"), position_of(text, "[7"), "a number deep in arrays");
    expect_at(positions.at("/a~1b"), position_of(text, "\"a/b\""), "a key with a slash");
    expect_at(positions.at("/q\"uote"), position_of(text, "\"q\\"), "a key with an escaped quote");
    expect_at(positions.at("/last"), position_of(text, "\"last\""), "after a comma");
    expect_at(positions.at("/list/2/missing/deeper"), position_of(text, "{\"inner\""),
              "the nearest there is");
    EXPECT_EQ(positions.at("/nothing").file, source);  // the root
    EXPECT_EQ(json_pointer_token("a~b/c"), "a~0b~1c");
}

TEST(JsonPositions, MalformedJsonIsAnErrorWhereItStopsBeingJson) {
    const std::string text = "{\n  \"asset\": {\"version\": \"2.0\"},\n  \"nodes\": [1, 2,, 3]\n}";
    try {
        JsonPositions(SourceFile::from_text("bad.json", text), {});
        FAIL() << "malformed JSON was read";
    } catch (const SceneError& e) {
        LineColumn second_comma = position_of(text, ",,");
        second_comma.column += 1;
        expect_at(e.position(), second_comma, e.what());
        EXPECT_EQ(e.message().rfind("malformed JSON: syntax error while parsing value", 0), 0u) << e.what();
    }
    // Cut short: just past the last byte.
    try {
        JsonPositions(SourceFile::from_text("short.json", "{\"a\": [1,\n 2"), {});
        FAIL() << "truncated JSON was read";
    } catch (const SceneError& e) {
        expect_at(e.position(), {2, 3}, e.what());
    }
}

// A model that uses what glint leaves out, one construct per line. "DATA" is the buffer's URI.
constexpr std::string_view kModel = R"({
  "asset": {"version": "2.0"},
  "extensionsUsed": ["KHR_lights_punctual", "EXT_unheard_of"],
  "scene": 0,
  "scenes": [{"nodes": [0, 1, 2]}],
  "nodes": [
    {"mesh": 0},
    {"mesh": 1, "skin": 0},
    {"extensions": {"KHR_lights_punctual": {"light": 0}}}
  ],
  "meshes": [
    {"name": "square", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]},
    {"name": "dots", "primitives": [{"attributes": {"POSITION": 0}, "mode": 0}]}
  ],
  "skins": [{"joints": [0], "inverseBindMatrices": 0}],
  "materials": [
    {
      "name": "brick",
      "occlusionTexture": {"index": 0},
      "alphaMode": "BLEND",
      "normalTexture": {"index": 0},
      "pbrMetallicRoughness": {
        "baseColorTexture": {"index": 0, "texCoord": 1,
                             "extensions": {"KHR_texture_transform": {"scale": [2, 2]}}}
      },
      "extensions": {"KHR_materials_sheen": {}}
    }
  ],
  "textures": [{"source": 0}],
  "images": [{"uri": "brick.png"}],
  "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "range": 5}]}},
  "buffers": [{"byteLength": 60DATA}],
  "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
    {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}
  ]
}
)";

// kModel with its buffer: a data: URI (`uri` true), or none, for a .glb's binary chunk.
std::string model_text(bool uri) {
    std::string text(kModel);
    text.replace(
        text.find("DATA"), 4,
        uri ? ", \"uri\": \"data:application/octet-stream;base64," + test::base64(test::square_bytes()) + "\""
            : "");
    return text;
}

// Each warning of the model, by a piece of its message, and the text its position must be at.
struct ExpectedWarning {
    const char* message;
    const char* at;
};
constexpr ExpectedWarning kExpectedWarnings[] = {
    {"the extension EXT_unheard_of is not read", "\"EXT_unheard_of\""},
    {"node '' is skinned", "\"skin\""},
    {"is made of points or lines", "\"mode\""},
    {"has a range", "\"range\""},
    {"its occlusion map is ignored", "\"occlusionTexture\""},
    {"alphaMode BLEND is rendered opaque", "\"alphaMode\""},
    {"KHR_materials_sheen is not read", "\"KHR_materials_sheen\""},
    {"base colour map uses TEXCOORD_1", "\"texCoord\""},
    {"base colour map has a KHR_texture_transform", "\"KHR_texture_transform\""},
    {"has no TEXCOORD_0: the normal map", "\"attributes\""},  // the first primitive's
    {"has no camera", "{\"nodes\""},                          // the scene's
};

void expect_warnings_at_their_elements(const SceneDesc& desc, const std::string& text,
                                       const std::string& file) {
    for (const ExpectedWarning& expected : kExpectedWarnings) {
        const SceneWarning* found = nullptr;
        for (const SceneWarning& warning : desc.warnings) {
            if (warning.message.find(expected.message) != std::string::npos) {
                found = &warning;
            }
        }
        ASSERT_NE(found, nullptr) << "no warning '" << expected.message << "'";
        expect_at(found->pos, position_of(text, expected.at), found->to_string());
        ASSERT_NE(found->pos.file, nullptr);
        EXPECT_EQ(found->pos.file->path, file);
    }
    EXPECT_EQ(desc.warnings.size(), std::size(kExpectedWarnings));
}

TEST(GltfPositions, EveryWarningIsAtItsElementInTheGltf) {
    test::TempDir dir;
    const std::string text = model_text(true);
    dir.write("model.gltf", text);
    const SceneDesc desc = load_scene(dir / "model.gltf");
    expect_warnings_at_their_elements(desc, text, (dir / "model.gltf").string());
    // As printed: file:line:col, the line, a caret.
    const LineColumn occlusion = position_of(text, "\"occlusionTexture\"");
    for (const SceneWarning& warning : desc.warnings) {
        if (warning.message.find("occlusion") != std::string::npos) {
            EXPECT_EQ(warning.to_string().rfind((dir / "model.gltf").string() + ":" +
                                                    std::to_string(occlusion.line) + ":" +
                                                    std::to_string(occlusion.column) + ": warning: ",
                                                0),
                      0u)
                << warning.to_string();
            EXPECT_NE(
                warning.to_string().find("\n          \"occlusionTexture\": {\"index\": 0},\n          ^"),
                std::string::npos)
                << warning.to_string();
        }
    }
    // A node made from an element is at it too: a build error (the image file is missing) points at the
    // image's uri.
    try {
        build_scene(desc);
        FAIL() << "brick.png does not exist";
    } catch (const SceneError& e) {
        expect_at(e.position(), position_of(text, "\"uri\": \"brick.png\""), e.what());
    }
}

TEST(GltfPositions, AGlbsWarningsAreAtTheirElementInItsJsonChunk) {
    test::TempDir dir;
    const std::string text = model_text(false);
    dir.write("model.glb", test::glb(text, test::square_bytes()));
    const SceneDesc desc = load_scene(dir / "model.glb");
    expect_warnings_at_their_elements(desc, text, (dir / "model.glb").string() + " (JSON chunk)");
    // Malformed JSON in the chunk: at its line and column there (the 'x' where a value should be).
    const std::string broken = "{\"asset\": {\"version\": \"2.0\"},\n \"nodes\": x}";
    dir.write("broken.glb", test::glb(broken, test::square_bytes()));
    try {
        load_scene(dir / "broken.glb");
        FAIL() << "malformed JSON was read";
    } catch (const SceneError& e) {
        expect_at(e.position(), position_of(broken, "x}"), e.what());
        EXPECT_EQ(e.position().file->path, (dir / "broken.glb").string() + " (JSON chunk)");
    }
}

// Importing `text` (as `name` in `dir`) is an error at `expected` whose message holds `reason`.
void expect_import_error(const test::TempDir& dir, const std::string& name, const std::string& text,
                         LineColumn expected, const std::string& reason) {
    dir.write(name, text);
    try {
        load_scene(dir / name);
        ADD_FAILURE() << name << " was read";
    } catch (const SceneError& e) {
        expect_at(e.position(), expected, e.what());
        EXPECT_NE(e.message().find(reason), std::string::npos) << e.what();
    }
}

TEST(GltfPositions, MalformedJsonIsAPositionedErrorExit2AndNoImage) {
    test::TempDir dir;
    std::string text = model_text(true);
    text.replace(text.find("\"alphaMode\": \"BLEND\","), 21, "\"alphaMode\" \"BLEND\",");  // no colon
    LineColumn expected = position_of(text, "\"alphaMode\" \"BLEND\"");
    expected.column += 18;  // the end of the string where the ':' should be: the last byte read
    expect_import_error(dir, "broken.gltf", text, expected,
                        "malformed JSON: syntax error while parsing object separator");
    const auto cli = test::run_glint("render '" + (dir / "broken.gltf").string() + "' -o '" +
                                     (dir / "broken.png").string() + "' -q");
    EXPECT_EQ(cli.exit_code, 2) << cli.output;
    EXPECT_NE(cli.output.find("broken.gltf:" + std::to_string(expected.line) + ":" +
                              std::to_string(expected.column) + ": error: "),
              std::string::npos)
        << cli.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "broken.png"));
}

TEST(GltfPositions, TinygltfsReasonsAreAtTheElementTheyName) {
    test::TempDir dir;
    // The second buffer has no byteLength: tinygltf says "'byteLength' property is missing in Buffer".
    std::string text = model_text(true);
    text.replace(text.find("}],\n  \"bufferViews\""), 2, "}, {\"uri\": \"more.bin\"}]");
    expect_import_error(dir, "buffers.gltf", text, position_of(text, "{\"uri\": \"more.bin\"}"),
                        "'byteLength' property is missing");
    // An accessor reaching past its buffer: at the primitive that reads it.
    text = model_text(true);
    text.replace(text.find("\"count\": 4"), 10, "\"count\": 5");
    expect_import_error(dir, "long.gltf", text, position_of(text, "{\"attributes\""),
                        "POSITION accessor 0 (5 elements) reaches past its buffer");
    // A node that does not exist: at the list that names it (its numbers are not kept one by one).
    text = model_text(true);
    text.replace(text.find("[0, 1, 2]"), 9, "[0, 1, 7]");
    expect_import_error(dir, "nodes.gltf", text, position_of(text, "\"nodes\": [0, 1, 7]"),
                        "node 7 does not exist");
}

}  // namespace
}  // namespace glint
