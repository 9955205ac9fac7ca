// One test per class of scene error: each must be reported at the right line and column.
#include <gtest/gtest.h>

#include "glint/core/hash.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

struct Reported {
    int line = 0;
    int column = 0;
    std::string message;
    std::string report;
};

Reported error_of(const std::string& yaml) {
    try {
        build_scene(parse_scene_text(yaml, "bad.yaml", "."));
    } catch (const SceneError& e) {
        return {e.position().line, e.position().column, e.message(), e.what()};
    }
    ADD_FAILURE() << "no error for:\n" << yaml;
    return {};
}

TEST(SceneErrors, YamlSyntaxError) {
    const Reported r = error_of("objects:\n  - {type: sphere, radius: 1\nlights: []\n");
    EXPECT_EQ(r.line, 3);
    EXPECT_NE(r.message.find("syntax error"), std::string::npos) << r.report;
}

TEST(SceneErrors, UnknownKeyWithDidYouMean) {
    const Reported r = error_of("objects:\n  - type: sphere\n    radious: 1\n");
    EXPECT_EQ(r.line, 3);
    EXPECT_EQ(r.column, 5);
    EXPECT_NE(r.message.find("did you mean 'radius'"), std::string::npos) << r.report;
}

TEST(SceneErrors, UnknownKeyAmongOptionalOnes) {
    const Reported r = error_of("render:\n  width: 10\n  sampels: 4\n");
    EXPECT_EQ(r.line, 3);
    EXPECT_EQ(r.column, 3);
    EXPECT_NE(r.message.find("did you mean 'samples'"), std::string::npos) << r.report;
}

TEST(SceneErrors, UnknownTopLevelKey) {
    const Reported r = error_of("objets: []\n");
    EXPECT_EQ(r.line, 1);
    EXPECT_EQ(r.column, 1);
    EXPECT_NE(r.message.find("did you mean 'objects'"), std::string::npos) << r.report;
}

TEST(SceneErrors, WrongType) {
    const Reported r = error_of("objects:\n  - {type: sphere, center: [0, 0], radius: 1}\n");
    EXPECT_EQ(r.line, 2);
    EXPECT_EQ(r.column, 28);
    EXPECT_NE(r.message.find("three numbers"), std::string::npos) << r.report;

    const Reported word = error_of("render: {width: wide}\n");
    EXPECT_EQ(word.line, 1);
    EXPECT_EQ(word.column, 17);
    EXPECT_NE(word.message.find("must be a number"), std::string::npos) << word.report;
}

TEST(SceneErrors, MissingKey) {
    const Reported r = error_of("lights:\n  - {type: point, intensity: 5}\n");
    EXPECT_EQ(r.line, 2);
    EXPECT_EQ(r.column, 5);
    EXPECT_NE(r.message.find("needs 'position'"), std::string::npos) << r.report;
}

TEST(SceneErrors, NegativeRadius) {
    const Reported r = error_of("objects:\n  - {type: sphere, radius: -2}\n");
    EXPECT_EQ(r.line, 2);
    EXPECT_EQ(r.column, 28);
    EXPECT_NE(r.message.find("greater than zero"), std::string::npos) << r.report;
}

TEST(SceneErrors, ZeroNormal) {
    const Reported r = error_of("objects:\n  - {type: plane, normal: [0, 0, 0]}\n");
    EXPECT_EQ(r.line, 2);
    EXPECT_EQ(r.column, 27);
    EXPECT_NE(r.message.find("non-zero"), std::string::npos) << r.report;
}

TEST(SceneErrors, UpParallelToViewDirection) {
    const Reported r = error_of("camera:\n  eye: [0, 5, 0]\n  look_at: [0, 0, 0]\n  up: [0, 2, 0]\n");
    EXPECT_EQ(r.line, 4);
    EXPECT_EQ(r.column, 7);
    EXPECT_NE(r.message.find("parallel"), std::string::npos) << r.report;
}

TEST(SceneErrors, ZeroSamples) {
    const Reported r = error_of("render:\n  samples: 0\n");
    EXPECT_EQ(r.line, 2);
    EXPECT_EQ(r.column, 12);
    EXPECT_NE(r.message.find("greater than zero"), std::string::npos) << r.report;
}

TEST(SceneErrors, UnknownMaterialName) {
    const Reported r = error_of(
        "materials:\n  chrome: {type: matte}\nobjects:\n  - {type: sphere, radius: 1, material: crome}\n");
    EXPECT_EQ(r.line, 4);
    EXPECT_EQ(r.column, 41);
    EXPECT_NE(r.message.find("did you mean 'chrome'"), std::string::npos) << r.report;
}

TEST(SceneErrors, UnknownTypeListsTheKnownOnes) {
    const Reported r = error_of("objects:\n  - {type: sphre, radius: 1}\n");
    EXPECT_EQ(r.line, 2);
    EXPECT_EQ(r.column, 12);
    EXPECT_NE(r.message.find("did you mean 'sphere'"), std::string::npos) << r.report;
    EXPECT_NE(r.message.find("plane"), std::string::npos) << r.report;
}

TEST(SceneErrors, ReportQuotesTheLineWithACaret) {
    const Reported r = error_of("objects:\n  - {type: sphere, radius: -2}\n");
    EXPECT_EQ(r.report,
              "bad.yaml:2:28: error: sphere.radius must be greater than zero, not -2\n"
              "      - {type: sphere, radius: -2}\n"
              "                               ^");
}

TEST(SceneErrors, CommandLineRejectsABadSceneWithExitCode2AndNoOutput) {
    test::TempDir dir;
    const auto scene = dir.write("bad.yaml", "objects:\n  - {type: sphere, radius: -1}\n");
    const auto out = dir / "out.png";
    const test::CommandResult r =
        test::run_glint("render '" + scene.string() + "' -o '" + out.string() + "' --quiet");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("bad.yaml:2:28: error:"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);  // no temp file left
}

TEST(SceneErrors, MissingFileIsBadInput) {
    const test::CommandResult r = test::run_glint("render /nonexistent/scene.yaml -o /tmp/x.png --quiet");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("/nonexistent/scene.yaml"), std::string::npos) << r.output;
}

TEST(SceneErrors, JsonScenesAreReadWithPositions) {
    const Reported r = error_of("{\n  \"objects\": [\n    {\"type\": \"sphere\", \"radius\": 0}\n  ]\n}\n");
    EXPECT_EQ(r.line, 3);
    EXPECT_EQ(r.column, 34);
}

}  // namespace
}  // namespace glint

namespace glint {
namespace {

TEST(SceneErrors, LongLinesAreQuotedAroundTheColumnOnly) {
    const std::string padding(5000, ' ');
    const Reported r = error_of("objects: [" + padding + "{type: sphere, radius: -1}]\n");
    EXPECT_EQ(r.line, 1);
    EXPECT_EQ(r.column, 5034);
    EXPECT_LT(r.report.size(), 400u) << r.report;
    // The caret still sits under the offending value.
    const auto last_line = r.report.substr(r.report.rfind('\n') + 1);
    const auto quoted = r.report.substr(0, r.report.rfind('\n'));
    const auto quoted_line = quoted.substr(quoted.rfind('\n') + 1);
    EXPECT_EQ(quoted_line.substr(last_line.size() - 1, 2), "-1");
}

// Malformed input of any kind is a SceneError, never a crash or another exception: every
// truncation of the default scene, and many random byte changes to it.
TEST(SceneErrors, MutatedScenesFailCleanly) {
    const std::string text = default_scene_text();
    int errors = 0;
    const auto attempt = [&](const std::string& mutated) {
        try {
            RenderFlags small;
            small.width = 4;
            small.height = 4;
            build_scene(parse_scene_text(mutated, "mutated.yaml", "."), small);
        } catch (const SceneError&) {
            ++errors;
        }
    };
    for (size_t n = 0; n < text.size(); n += 3) {
        attempt(text.substr(0, n));
    }
    const std::string alphabet = "-:[]{},#'\"\t\n 0.e9xyz";
    for (std::uint32_t i = 0; i < 3000; ++i) {
        std::string mutated = text;
        const SampleKey key{99, i, 0, 0};
        for (int k = 0; k < 3; ++k) {
            const size_t at = static_cast<size_t>(key.uniform(2 * k) * mutated.size());
            mutated[at] = alphabet[static_cast<size_t>(key.uniform(2 * k + 1) * alphabet.size())];
        }
        attempt(mutated);
    }
    EXPECT_GT(errors, 1000);  // most mutations are errors; none escaped as anything else
}

}  // namespace
}  // namespace glint
