// Scene text is untrusted: each limit of docs/scene-format.md ("Limits") gives a positioned error, never
// a crash, a hang or unbounded memory.
#include <gtest/gtest.h>
#include <pthread.h>
#include <sys/stat.h>

#include <filesystem>

#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"
#include "glint/world/settings.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

// The error `text` gives, parsed and built as the command line does; fails the test if there is none.
SceneError error_of(const std::string& text, const RenderFlags& overrides = {}) {
    try {
        build_scene(parse_scene_text(text, "bad.yaml", "."), overrides);
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << text.substr(0, 200);
    return SceneError({}, "");
}

bool says(const SceneError& e, const std::string& part) {
    return e.message().find(part) != std::string::npos;
}

TEST(SceneLimits, AnAliasInsideItsOwnAnchorIsAnError) {
    // An alias stands for the value it names, so these are values that contain themselves.
    for (const std::string text :
         {"&a [*a]", "objects: &a [*a]\n", "a: &a {b: *a}\n", "a: &a {b: [1, {c: *a}]}\n"}) {
        const SceneError e = error_of(text);
        EXPECT_TRUE(says(e, "contains an alias of itself")) << e.what();
        EXPECT_EQ(e.position().line, 1) << e.what();
    }
}

TEST(SceneLimits, AnAliasBombStopsAtTheValueLimit) {
    // Eleven levels of ten aliases each: 10^11 values if expanded.
    std::string text = "a0: &a0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\n";
    for (int i = 1; i <= 11; ++i) {
        const std::string name = std::to_string(i), previous = std::to_string(i - 1);
        text.append("a").append(name).append(": &a").append(name).append(" [");
        for (int j = 0; j < 10; ++j) {
            text.append(j ? ", *a" : "*a").append(previous);
        }
        text += "]\n";
    }
    const SceneError e = error_of(text);
    EXPECT_TRUE(says(e, "more than " + std::to_string(kMaxSceneValues) + " values")) << e.what();
}

TEST(SceneLimits, ALongTextRepeatedByAliasesStopsAtTheByteLimit) {
    // 1 MiB repeated by 300 aliases: 300 MiB of strings from a file of 1 MiB and few values.
    std::string text = "s: &s \"" + std::string(std::size_t{1} << 20, 'x') + "\"\na: [";
    for (int i = 0; i < 300; ++i) {
        text.append(i ? ", *s" : "*s");
    }
    text += "]\n";
    const SceneError e = error_of(text);
    EXPECT_TRUE(says(e, "more than " + std::to_string(kMaxSceneValueBytes) + " bytes")) << e.message();
}

TEST(SceneLimits, AliasesWithinTheLimitStillWork) {
    const Scene scene = test::scene_from_text(
        "materials:\n  red: &red {type: matte, albedo: [0.8, 0.1, 0.1]}\n  red2: *red\n"
        "objects:\n  - {type: sphere, radius: 1, material: red2}\n");
    EXPECT_EQ(scene.world->materials.size(), 2u);
}

TEST(SceneLimits, DeepNestingIsAnError) {
    const auto nested = [](int depth) { return "a: " + std::string(depth, '[') + std::string(depth, ']'); };
    for (const std::size_t depth : {kMaxSceneNesting + 1, std::size_t{3000}, std::size_t{100000}}) {
        const SceneError e = error_of(nested(static_cast<int>(depth)));
        EXPECT_TRUE(says(e, "nests deeper than " + std::to_string(kMaxSceneNesting))) << e.what();
        EXPECT_EQ(e.position().line, 1);
    }
    // Nesting reached through an alias counts too: 60 levels inside 60 levels.
    const std::string sixty_open(60, '['), sixty_close(60, ']');
    const SceneError e = error_of("a: &deep " + sixty_open + sixty_close + "\nb: " + sixty_open + "*deep" +
                                  sixty_close + "\n");
    EXPECT_TRUE(says(e, "nests deeper")) << e.what();
}

TEST(SceneLimits, Utf16AndZeroBytesAreRefusedWithTheReason) {
    // "objects: []" in UTF-16 little endian, with and without its byte-order mark.
    std::string utf16;
    for (char c : std::string("objects: []\nwidth: 1\n")) {
        utf16 += c;
        utf16 += '\0';
    }
    const SceneError with_bom = error_of("\xFF\xFE" + utf16);
    EXPECT_TRUE(says(with_bom, "UTF-16")) << with_bom.what();
    const SceneError without_bom = error_of(utf16);
    EXPECT_TRUE(says(without_bom, "zero byte")) << without_bom.what();
    EXPECT_EQ(without_bom.position().line, 1);
    EXPECT_EQ(without_bom.position().column, 2);
    // The quoted line shows no raw control characters.
    EXPECT_EQ(std::string(without_bom.what()).find('\0'), std::string::npos);
    const SceneError utf32 = error_of(std::string("\xFF\xFE\0\0o\0\0\0", 8));
    EXPECT_TRUE(says(utf32, "UTF-32")) << utf32.what();
}

TEST(SceneLimits, APositionPastTheEndOfItsLineIsStillReported) {
    // A parser that counts characters of another encoding can hand over such a column.
    const auto file = SourceFile::from_text("x.yaml", "ab\n");
    const std::string report = format_diagnostic({file, 1, 1000}, "message");
    EXPECT_NE(report.find("x.yaml:1:1000: error: message"), std::string::npos) << report;
    EXPECT_NE(report.find("ab\n      ^"), std::string::npos) << report;
    EXPECT_NO_THROW(format_diagnostic({file, 5, -3}, "a line past the end"));
}

TEST(SceneLimits, ScenesLargerThanTheLimitAreNotRead) {
    test::TempDir dir;
    const auto big = dir / "big.yaml";
    std::ofstream(big) << "objects: []\n";
    std::filesystem::resize_file(big, kMaxSceneFileBytes + 1);  // sparse: nothing is written
    try {
        load_scene_file(big);
        ADD_FAILURE() << "a scene over the size limit was read";
    } catch (const SceneError& e) {
        EXPECT_TRUE(says(e, "more than " + std::to_string(kMaxSceneFileBytes))) << e.what();
    }
}

TEST(SceneLimits, OnlyRegularFilesAreRead) {
    test::TempDir dir;
    const auto fifo = dir / "pipe.yaml";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    for (const std::filesystem::path& path : {dir.path(), fifo, std::filesystem::path("/dev/zero")}) {
        try {
            load_scene_file(path);
            ADD_FAILURE() << path << " was read as a scene";
        } catch (const SceneError& e) {
            EXPECT_TRUE(says(e, "not a regular file")) << e.what();
        }
    }
}

TEST(SceneLimits, MaxDepthHasAnUpperBound) {
    const SceneError in_file = error_of("render:\n  integrator: whitted\n  max_depth: 1000000000\n");
    EXPECT_EQ(in_file.position().line, 3);
    EXPECT_TRUE(says(in_file, "more than " + std::to_string(kMaxPathDepth) + " bounces")) << in_file.what();
    RenderFlags deep;
    deep.max_depth = 30000;
    const SceneError on_command_line = error_of("objects: []\n", deep);
    // The flag is a short form of --set render.max_depth=…: the error names both.
    EXPECT_EQ(on_command_line.position().file->path, "--max-depth") << on_command_line.what();
    EXPECT_TRUE(says(on_command_line, "render.max_depth is more than")) << on_command_line.what();
}

TEST(SceneLimits, ImageSizeAndSamplesHaveUpperBounds) {
    EXPECT_TRUE(says(error_of("render: {width: 40000}\n"), "larger than 32768 pixels"));
    EXPECT_TRUE(says(error_of("render: {samples: 2000000}\n"), "more than 1048576 per pixel"));
    // Each side within its limit, the whole too large for the film.
    const SceneError whole = error_of("render: {width: 32768, height: 32768}\n");
    EXPECT_TRUE(says(whole, "the film would need more than 4 GiB")) << whole.what();
    EXPECT_EQ(whole.position().line, 1);
    RenderFlags wide;
    wide.width = 32768;
    wide.height = 16384;
    EXPECT_TRUE(says(error_of("objects: []\n", wide), "more than 134217728 pixels"));
    RenderFlags zero;
    zero.width = 0;
    const SceneError zero_width = error_of("objects: []\n", zero);
    EXPECT_EQ(zero_width.position().file->path, "--width") << zero_width.what();
    EXPECT_TRUE(says(zero_width, "render.width")) << zero_width.what();
}

// Whitted's recursion runs as a loop: the deepest allowed value between two facing mirrors (every
// branch goes the whole depth) finishes on a thread with a 256 KiB stack, where the old recursion
// (hundreds of bytes a level, over 1024 levels) overflowed.
TEST(SceneLimits, WhittedAtTheDeepestAllowedDepthNeedsLittleStack) {
    Scene scene =
        test::scene_from_text("render: {width: 4, height: 4, samples: 1, integrator: whitted, max_depth: " +
                              std::to_string(kMaxPathDepth) + "}\n" +
                              "camera: {eye: [0, 0, 0], look_at: [0, 0, -1], fov: 10}\n"
                              "materials: {m: {type: mirror}}\n"
                              "objects:\n"
                              "  - {type: plane, point: [0, 0, -1], normal: [0, 0, 1], material: m}\n"
                              "  - {type: plane, point: [0, 0, 1], normal: [0, 0, -1], material: m}\n"
                              "lights: [{type: point, position: [0, 0, 0], intensity: 1}]\n");
    scene.view.settings.threads = 1;  // render() then runs on the calling thread: the small one below
    struct Job {
        const Scene* scene;
        RenderStats stats;
    } job{&scene, {}};
    pthread_attr_t attributes;
    pthread_attr_init(&attributes);
    ASSERT_EQ(pthread_attr_setstacksize(&attributes, 256 * 1024), 0);
    pthread_t thread;
    ASSERT_EQ(pthread_create(
                  &thread, &attributes,
                  [](void* argument) -> void* {
                      auto* j = static_cast<Job*>(argument);
                      test::render_film(*j->scene, &j->stats);
                      return nullptr;
                  },
                  &job),
              0);
    pthread_join(thread, nullptr);
    pthread_attr_destroy(&attributes);
    EXPECT_EQ(job.stats.nonfinite_samples, 0u);
    // Every camera ray is reflected the whole depth: the mirror room never lets a branch escape.
    EXPECT_EQ(job.stats.rays.secondary, 16u * kMaxPathDepth);
}

}  // namespace
}  // namespace glint
