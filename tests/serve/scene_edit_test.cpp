// Edits of the scene tree from the page: JSON values become scene text that reads back the same,
// paths are created or removed, and what is not allowed is refused with a reason.
#include "glint/serve/scene_edit.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>

#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_writer.hpp"
#include "glint/serve/preview_server.hpp"
#include "glint/serve/preview_session.hpp"
#include "glint/serve/serve_limits.hpp"

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

// The value each limit stands at, written out here rather than taken from serve_limits.hpp, so that a
// change of a limit is a visible change of this test (and of the README, which lists them).
TEST(SceneEdit, EditsPastAPreviewLimitNameTheKeyTheValueAndTheMaximum) {
    struct Case {
        const char* body;
        const char* key;
        double value;
        std::int64_t maximum;
    };
    const Case cases[] = {
        {R"({"path": ["render", "width"], "value": 4097})", "render.width", 4097, 4096},
        {R"({"path": ["render", "height"], "value": 30000})", "render.height", 30000, 4096},
        {R"({"path": ["render", "samples"], "value": 16385})", "render.samples", 16385, 16384},
        {R"({"edits": [{"path": ["render", "integrator"], "value": "whitted"},
                       {"path": ["render", "max_depth"], "value": 100000000}]})",
         "render.max_depth", 1e8, 64},
        {R"({"path": ["render", "max_depth"], "value": 1e300})", "render.max_depth", 1e300, 64},
        {R"({"edits": [{"path": ["render", "width"], "value": 4096},
                       {"path": ["render", "height"], "value": 1025}]})",
         "render.width × render.height", 4096.0 * 1025, 2048 * 2048},
    };
    const SceneDesc loaded = default_scene();
    for (const Case& c : cases) {
        try {
            apply_edit_request(loaded, c.body);
            ADD_FAILURE() << "accepted: " << c.body;
        } catch (const PreviewLimitError& e) {
            EXPECT_EQ(e.key, c.key) << c.body;
            EXPECT_EQ(e.value, c.value) << c.body;
            EXPECT_EQ(e.maximum, c.maximum) << c.body;
            const std::string message = e.what();
            EXPECT_NE(message.find(c.key), std::string::npos) << message;
            EXPECT_NE(message.find("at most " + std::to_string(c.maximum)), std::string::npos) << message;
        }
    }
    // At the limits: accepted.
    for (const char* body : {R"({"path": ["render", "max_depth"], "value": 64})",
                             R"({"path": ["render", "samples"], "value": 16384})",
                             R"({"edits": [{"path": ["render", "width"], "value": 4096},
                                          {"path": ["render", "height"], "value": 1024}]})"}) {
        EXPECT_NO_THROW(apply_edit_request(loaded, body)) << body;
    }
}

TEST(SceneEdit, TheFuzzEntryPointReturnsTheEditedDescriptionParsedBackFromItsYaml) {
    const SceneDesc loaded = default_scene();
    const EditedScene edited = apply_edit_request(
        loaded,
        R"({"edits": [{"path": ["camera", "fov"], "value": 20}, {"path": ["render", "max_depth"], "value": 7}]})");
    EXPECT_EQ(edited.desc.root.find("camera")->find("fov")->scalar, "20");
    EXPECT_EQ(edited.desc.root.find("render")->find("max_depth")->scalar, "7");
    EXPECT_EQ(edited.desc.base_dir, loaded.base_dir);
    EXPECT_TRUE(same_tree(edited.desc.root, parse_scene_text(edited.yaml, "<t>", ".").root));
    // Positions point into the YAML the page exports.
    EXPECT_EQ(edited.desc.root.find("camera")->find("fov")->pos.file->path, "<scene in the browser>");
}

// Measures how long `f` takes, for the checks that bad input is refused at once.
double seconds_for(const std::function<void()>& f) {
    const auto start = std::chrono::steady_clock::now();
    f();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(SceneEdit, BadBodiesAreTypedErrorsAtOnce) {
    const SceneDesc loaded = default_scene();
    const auto error_of = [&](const std::string& body) -> std::string {
        try {
            apply_edit_request(loaded, body);
        } catch (const RequestTooLargeError&) {
            return "too large";
        } catch (const PreviewLimitError&) {
            return "limit";
        } catch (const FileReferenceError&) {
            return "file";
        } catch (const EditError& e) {
            return e.what();
        }
        return "";
    };
    // Deep nesting, within the size limit: refused while parsing, before anything recursive runs.
    const std::string deep_array = std::string(30000, '[') + std::string(30000, ']');
    const std::string deep_object = [] {
        std::string s;
        for (int i = 0; i < 5000; ++i) {
            s += R"({"a":)";
        }
        return s + "1" + std::string(5000, '}');
    }();
    std::string message;
    EXPECT_LT(seconds_for([&] { message = error_of(deep_array); }), 1.0);
    EXPECT_NE(message.find("nested more than 8"), std::string::npos) << message;
    EXPECT_NE(error_of(deep_object).find("nested more than 8"), std::string::npos);
    // Eight levels are allowed: the limit is where the test says.
    EXPECT_EQ(error_of(R"({"path": ["camera", "eye"], "value": [[[[[[[1]]]]]]]})").find("nested"),
              std::string::npos);

    // One byte over the body limit (64 KiB): refused before parsing.
    std::string huge = R"({"path": ["camera", "type"], "value": ")";
    huge += std::string(64 * 1024 - huge.size() - 2 + 1, 'a') + "\"}";
    ASSERT_EQ(huge.size(), 64u * 1024 + 1);
    EXPECT_EQ(error_of(huge), "too large");
    // Just under it: a giant word, refused for what it is, its echo cut short.
    huge.erase(huge.size() - 3, 1);
    message = error_of(huge);
    EXPECT_NE(message.find("one word"), std::string::npos);
    EXPECT_LT(message.size(), 400u);

    EXPECT_NE(
        error_of(R"({"path": ["camera", "fov"], "value": 1e999})").find("not valid JSON: number overflow"),
        std::string::npos);
    EXPECT_NE(error_of(R"({"path": ["camera", "fov"], "value": NaN})").find("not valid JSON"),
              std::string::npos);
    EXPECT_NE(error_of(R"({"path": ["camera", "fov"], "value": Infinity})").find("not valid JSON"),
              std::string::npos);
    EXPECT_NE(error_of("").find("not valid JSON"), std::string::npos);
    // The parser's message quotes the input: it is shortened.
    EXPECT_LT(error_of(R"({"path": ["camera", "fov"], "value": ")" + std::string(50000, 'x')).size(), 400u);
    EXPECT_NE(error_of(std::string("{\"path\": [\"camera\"], \"value\": \"\xff\"}")).find("not valid JSON"),
              std::string::npos);
}

// A word cut for the message must stay valid UTF-8: the server dumps the message as JSON.
TEST(SceneEdit, AnEchoedValueIsCutAtACharacterBoundary) {
    const std::string value = std::string(63, 'a') + "\xc3\xa9" + std::string(10, 'b');  // é across byte 64
    try {
        parse_edits(json{{"path", {"camera", "type"}}, {"value", value}});
        FAIL();
    } catch (const EditError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(std::string(63, 'a') + "…"), std::string::npos) << message;
        EXPECT_NO_THROW((void)json(message).dump());
    }
}

// The scene of these tests refers to one file, `wood`, from a texture; it has an inline material and a
// light too.
SceneDesc scene_with_a_texture() {
    return parse_scene_text(R"(
materials:
  a: {type: matte, albedo: {type: image, file: wood}}
  b: {type: matte, albedo: [0.5, 0.5, 0.5]}
objects:
  - {type: sphere, radius: 1, material: a}
  - {type: sphere, center: [3, 0, 0], radius: 1, material: {type: matte, albedo: 0.5}}
lights:
  - {type: point, position: [0, 5, 0], intensity: 10}
)",
                            "t.yaml", "/nonexistent-dir");
}

TEST(SceneEdit, AnEditCannotMakeTheSceneReferToAnotherFile) {
    const SceneDesc loaded = scene_with_a_texture();
    EXPECT_EQ(file_references(loaded.root), std::set<std::string>{"wood"});
    const auto refusal = [&](const std::string& body) -> std::string {
        try {
            apply_edit_request(loaded, body);
        } catch (const FileReferenceError& e) {
            return e.what();
        } catch (const std::exception& e) {
            return std::string("other error: ") + e.what();
        }
        return "accepted";
    };
    // A new texture, built key by key, naming any file: the same fixed words for every name.
    const auto new_texture = [](const std::string& file) {
        return R"({"edits": [{"path": ["materials", "b", "albedo"], "value": null},
                             {"path": ["materials", "b", "albedo", "type"], "value": "image"},
                             {"path": ["materials", "b", "albedo", "file"], "value": ")" +
               file + R"("}]})";
    };
    for (const std::string name : {"passwd", "secret", "t", "nonexistent"}) {
        EXPECT_EQ(refusal(new_texture(name)), kFileReferenceRefused) << name;
    }
    // The existing texture pointed elsewhere, or a file key anywhere else in the tree.
    EXPECT_EQ(refusal(R"({"path": ["materials", "a", "albedo", "file"], "value": "other"})"),
              kFileReferenceRefused);
    EXPECT_EQ(refusal(R"({"path": ["materials", "b", "file"], "value": "x"})"), kFileReferenceRefused);
    EXPECT_EQ(refusal(R"({"path": ["camera", "image"], "value": "x"})"), kFileReferenceRefused);
    EXPECT_EQ(refusal(R"({"path": ["render", "file"], "value": 3})"), kFileReferenceRefused);
    // Through an inline material or a light as well.
    EXPECT_EQ(refusal(R"({"edits": [{"path": ["objects", 1, "material", "albedo"], "value": null},
                                    {"path": ["objects", 1, "material", "albedo", "type"], "value": "image"},
                                    {"path": ["objects", 1, "material", "albedo", "file"], "value": "x"}]})"),
              kFileReferenceRefused);
    EXPECT_EQ(refusal(R"({"path": ["lights", 0, "image"], "value": "sky"})"), kFileReferenceRefused);
    // What the scene already refers to may be used again, and everything else is untouched.
    EXPECT_EQ(refusal(new_texture("wood")), "accepted");
    EXPECT_EQ(refusal(R"({"path": ["materials", "a", "albedo", "file"], "value": "wood"})"), "accepted");
    EXPECT_EQ(refusal(R"({"path": ["materials", "a", "albedo"], "value": null})"), "accepted");
}

TEST(SceneEdit, ALoadedScenePastAPreviewLimitIsRefusedAtItsLine) {
    const SceneDesc desc =
        parse_scene_text("render:\n  integrator: whitted\n  max_depth: 1000\n", "deep.yaml", ".");
    try {
        PreviewSession session(desc, "deep");
        FAIL() << "started";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.position().line, 3);
        EXPECT_NE(e.message().find("render.max_depth is 1000; the preview allows at most 64"),
                  std::string::npos)
            << e.message();
    }
}

// What the fuzz harness relies on: whatever the body, apply_edit_request either returns or throws
// EditError (or a subclass) or SceneError. A fixed seed keeps this test the same on every run.
TEST(SceneEdit, MutatedRequestsOnlyEverThrowTypedErrors) {
    const SceneDesc loaded = scene_with_a_texture();
    const std::vector<std::string> seeds = {
        R"({"edits": [{"path": ["camera", "fov"], "value": 20}, {"path": ["render", "max_depth"], "value": 7}]})",
        R"({"path": ["materials", "a", "albedo", "file"], "value": "wood"})",
        R"({"path": ["materials", "b", "albedo"], "value": [0.1, 0.2, 0.3]})",
        R"({"path": ["render", "width"], "value": 4096})",
        R"({"path": ["objects", 1, "material", "albedo"], "value": 0.25})",
        R"({"edits": [{"path": ["lights", "0", "intensity"], "value": [1, 2, 3]}]})",
    };
    const std::vector<std::string> tokens = {"[",
                                             "]",
                                             "{",
                                             "}",
                                             ",",
                                             ":",
                                             "\"file\"",
                                             "\"image\"",
                                             "null",
                                             "1e308",
                                             "-1",
                                             "1e999",
                                             "\"\\u0000\"",
                                             "\"materials\"",
                                             "\"render\"",
                                             "\"max_depth\"",
                                             "\"objects\"",
                                             "\"lights\"",
                                             "\"material\"",
                                             "0",
                                             "1",
                                             "99999999999999999999",
                                             "\"\xc3\""};
    std::mt19937 random(12345);
    int returned = 0, refused = 0;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 3000; ++i) {
        std::string body = seeds[random() % seeds.size()];
        for (int m = 0, n = 1 + static_cast<int>(random() % 4); m < n && !body.empty(); ++m) {
            const size_t at = random() % body.size();
            switch (random() % 3) {
                case 0:
                    body.erase(at, 1 + random() % 4);
                    break;
                case 1:
                    body.insert(at, tokens[random() % tokens.size()]);
                    break;
                default:
                    body[at] = static_cast<char>(random() % 256);
            }
        }
        try {
            apply_edit_request(loaded, body);
            ++returned;
        } catch (const EditError&) {
            ++refused;
        } catch (const SceneError&) {
            ++refused;
        } catch (const std::exception& e) {
            ADD_FAILURE() << "untyped error " << e.what() << " for " << body;
        }
    }
    EXPECT_GT(returned, 0);
    EXPECT_GT(refused, 0);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
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
