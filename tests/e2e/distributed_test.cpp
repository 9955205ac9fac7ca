// One image rendered in parts (glint render --tile I/N, then glint merge) and over MPI ranks (mpirun
// glint render): the bytes must be those of one `glint render`, and parts that do not belong together
// must be refused with a message naming the file and what differs, exit 2 and no output file
// (docs/distributed.md).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "glint/image/image_io.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

std::vector<char> file_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The path in single quotes, for the shell (the temporary folders hold no quote).
std::string quoted(const std::filesystem::path& path) {
    std::string text = "'";
    text += path.string();
    text += '\'';
    return text;
}

// smallpt's scene path-traced: every pixel takes many random numbers, and its height (45 rows) does not
// divide into 4 or 3 equal bands, so the parts and the ranks' bands differ in size.
const std::string kScene = std::string(GLINT_SOURCE_DIR) + "/examples/smallpt.yaml";
const std::string kSize = " --width 64 --height 45 --spp 8 --quiet ";

// Renders the four parts of kScene into dir/part-I.exr, with `extra` flags for part `odd_part`.
void render_parts(const test::TempDir& dir, int odd_part = -1, const std::string& extra = "") {
    for (int i = 0; i < 4; ++i) {
        std::string arguments = "render '" + kScene + "'" + kSize;
        arguments += "--tile " + std::to_string(i) + "/4 ";
        if (i == odd_part) {
            arguments += extra;
        }
        arguments += " -o " + quoted(dir / ("part-" + std::to_string(i) + ".exr"));
        const auto r = test::run_glint(arguments);
        ASSERT_EQ(r.exit_code, 0) << r.output;
    }
}

TEST(TileParts, MergedPartsAreBitForBitTheWholeRender) {
    test::TempDir dir;
    for (const char* extension : {".pfm", ".exr"}) {
        const auto whole = test::run_glint("render '" + kScene + "'" + kSize + "-o " +
                                           quoted(dir / ("whole" + std::string(extension))));
        ASSERT_EQ(whole.exit_code, 0) << whole.output;
    }
    render_parts(dir);
    // Given out of order: the merge places each part by its number.
    const std::string parts = quoted(dir / "part-2.exr") + " " + quoted(dir / "part-0.exr") + " " +
                              quoted(dir / "part-3.exr") + " " + quoted(dir / "part-1.exr");
    for (const char* extension : {".pfm", ".exr"}) {
        const auto merged = dir / ("merged" + std::string(extension));
        const auto r = test::run_glint("merge " + parts + " -o " + quoted(merged));
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_NE(r.output.find("merged 4 parts"), std::string::npos) << r.output;
        const auto expected = file_bytes(dir / ("whole" + std::string(extension)));
        ASSERT_GT(expected.size(), 64u * 45u * 3u);
        EXPECT_TRUE(file_bytes(merged) == expected) << extension << " differs from the whole render";
    }
    // A part holds only its band: 45 rows in 4 parts are bands of 11, 11, 11 and 12 rows.
    EXPECT_EQ(read_image(dir / "part-0.exr").height, 11);
    EXPECT_EQ(read_image(dir / "part-3.exr").height, 12);
    const ExrFile part = read_exr(dir / "part-3.exr");
    EXPECT_EQ(part.attributes.at("glintPart"), "3/4");
    EXPECT_EQ(part.attributes.at("glintWindow"), "0,33,64,45");
    EXPECT_EQ(part.attributes.at("glintImageSize"), "64x45");
    EXPECT_EQ(part.attributes.at("glintSpp"), "8");
}

TEST(TileParts, AMergeIntoPngUsesTheExposureAndToneCurveThePartsRecord) {
    test::TempDir dir;
    const std::string display = kSize + "--exposure 1.5 --tonemap aces ";
    ASSERT_EQ(
        test::run_glint("render '" + kScene + "'" + display + "-o " + quoted(dir / "whole.png")).exit_code,
        0);
    std::string parts;
    for (int i = 0; i < 3; ++i) {
        const auto part = dir / ("part-" + std::to_string(i) + ".exr");
        const auto r = test::run_glint("render '" + kScene + "'" + display + "--tile " + std::to_string(i) +
                                       "/3 -o " + quoted(part));
        ASSERT_EQ(r.exit_code, 0) << r.output;
        parts += quoted(part) + " ";
    }
    const auto r = test::run_glint("merge " + parts + "-o " + quoted(dir / "merged.png"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(file_bytes(dir / "merged.png") == file_bytes(dir / "whole.png"));
}

// The merge's refusal: exit 2, a message holding each of `expected`, no output file.
void expect_refused(const std::string& parts, const test::TempDir& dir,
                    const std::vector<std::string>& expected) {
    const auto out = dir / "merged.pfm";
    const auto r = test::run_glint("merge " + parts + " -o " + quoted(out));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    for (const std::string& text : expected) {
        EXPECT_NE(r.output.find(text), std::string::npos) << "'" << text << "' not in: " << r.output;
    }
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(TileParts, MergeRefusesPartsThatDoNotBelongTogether) {
    test::TempDir dir;
    render_parts(dir, 2, "--seed 7");
    const auto part = [&](int i) { return quoted(dir / ("part-" + std::to_string(i) + ".exr")) + " "; };
    expect_refused(part(0) + part(1) + part(2) + part(3), dir,
                   {"part-2.exr: its seed is 7, but 1 in", "part-0.exr"});

    render_parts(dir, 1, "--set camera.fov=30");
    expect_refused(part(0) + part(1), dir, {"part-1.exr: its scene", "hash"});
    render_parts(dir, 3, "--set render.samples=4");
    expect_refused(part(0) + part(3), dir, {"part-3.exr: its samples per pixel is 4, but 8"});
    render_parts(dir, 3, "--set render.height=44");
    expect_refused(part(0) + part(3), dir, {"part-3.exr: its image size is 64x44, but 64x45"});

    render_parts(dir);
    expect_refused(part(0) + part(1) + part(3), dir, {"missing: 2"});
    expect_refused(part(0) + part(1) + part(1) + part(2) + part(3), dir, {"part 1/4 is given twice"});
    const auto other_count =
        test::run_glint("render '" + kScene + "'" + kSize + "--tile 1/3 -o " + quoted(dir / "third.exr"));
    ASSERT_EQ(other_count.exit_code, 0) << other_count.output;
    expect_refused(part(0) + quoted(dir / "third.exr"), dir, {"third.exr: its number of parts is 3, but 4"});

    // Files that are not parts at all.
    const auto whole = test::run_glint("render '" + kScene + "'" + kSize + "-o " + quoted(dir / "whole.exr"));
    ASSERT_EQ(whole.exit_code, 0) << whole.output;
    expect_refused(part(0) + quoted(dir / "whole.exr"), dir, {"whole.exr: not a part of a glint render"});
    const auto text = dir / "notes.exr";
    std::ofstream(text) << "not an image";
    expect_refused(part(0) + quoted(text), dir, {"notes.exr"});
}

TEST(TileParts, TheTileFlagIsChecked) {
    test::TempDir dir;
    const auto out = dir / "part.exr";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"--tile 4/4", "parts are numbered from 0 to 3"},
        {"--tile -1/4", "not a part I/N"},
        {"--tile 1", "not a part I/N"},
        {"--tile 0/0", "not a part I/N"},
        {"--tile 0/46", "the image has only 45 rows, fewer than 46 parts"},
        {"--tile 0/2 --crop 0,0,8,8", "--tile and --crop cannot be combined"},
        {"--tile 0/2 --set render.crop=[0,0,8,8]", "render.crop"},
        {"--tile 0/2 --time-limit 10", "--time-limit"},
    };
    for (const auto& [flags, message] : cases) {
        const auto r = test::run_glint("render '" + kScene + "'" + kSize + flags + " -o " + quoted(out));
        EXPECT_EQ(r.exit_code, 2) << flags << "\n" << r.output;
        EXPECT_NE(r.output.find(message), std::string::npos) << flags << "\n" << r.output;
        EXPECT_FALSE(std::filesystem::exists(out)) << flags;
    }
    for (const char* name : {"part.png", "part.pfm"}) {
        const auto r =
            test::run_glint("render '" + kScene + "'" + kSize + "--tile 0/2 -o " + quoted(dir / name));
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_NE(r.output.find("must be an OpenEXR file"), std::string::npos) << r.output;
        EXPECT_FALSE(std::filesystem::exists(dir / name));
    }
}

#ifdef GLINT_MPIEXEC
// mpirun with what the tests need: CI runs as root, which OpenMPI refuses unless told twice; the ranks
// share this machine's cores (--oversubscribe: 3 ranks on 2 cores). Under the sanitize preset, OpenMPI's
// own allocations that it never frees would trip LeakSanitizer in every rank at exit (they are MPI's,
// not glint's: glint's own leaks are caught by every other test, which runs without MPI), so leak
// detection is off for these runs only; ASan's and UBSan's other checks stay on.
// `before` goes between the environment and mpirun (a `timeout`).
std::string mpirun(int ranks, const std::string& before = "") {
    return "OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
           "ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0\" " +
           before + "'" GLINT_MPIEXEC "' --oversubscribe -np " + std::to_string(ranks) + " ";
}
const std::string kGlint = std::string("'") + GLINT_CLI_PATH + "'";

TEST(MpiRender, ThreeRanksGiveTheBitsOfOneProcess) {
    test::TempDir dir;
    for (const char* extension : {".pfm", ".exr"}) {
        const auto whole = test::run_glint("render '" + kScene + "'" + kSize + "-o " +
                                           quoted(dir / ("whole" + std::string(extension))));
        ASSERT_EQ(whole.exit_code, 0) << whole.output;
        const auto ranks = dir / ("ranks" + std::string(extension));
        const auto r = test::run_command(mpirun(3) + kGlint + " render '" + kScene + "'" + kSize + "-o " +
                                         quoted(ranks));
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_TRUE(file_bytes(ranks) == file_bytes(dir / ("whole" + std::string(extension)))) << extension;
    }
    // A crop window is cut into bands the same way.
    const std::string crop = "--crop 5,7,50,40 -o ";
    ASSERT_EQ(test::run_glint("render '" + kScene + "'" + kSize + crop + quoted(dir / "crop.pfm")).exit_code,
              0);
    const auto r = test::run_command(mpirun(2) + kGlint + " render '" + kScene + "'" + kSize + crop +
                                     quoted(dir / "ranks-crop.pfm"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(file_bytes(dir / "ranks-crop.pfm") == file_bytes(dir / "crop.pfm"));
}

// How many times `text` occurs in `output`.
size_t occurrences(const std::string& output, const std::string& text) {
    size_t count = 0;
    for (size_t at = output.find(text); at != std::string::npos; at = output.find(text, at + 1)) {
        ++count;
    }
    return count;
}

TEST(MpiRender, ABadSceneFailsOnceWithItsPosition) {
    test::TempDir dir;
    const auto scene = dir.write("bad.yaml", "render: {samplse: 4}\n");
    const auto out = dir / "out.pfm";
    const auto r = test::run_command(mpirun(3) + kGlint + " render " + quoted(scene) + " -o " + quoted(out));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    // Every rank finds the mistake; rank 0 alone says it.
    EXPECT_EQ(occurrences(r.output, "bad.yaml:1:10: error: unknown key 'samplse'"), 1u) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(MpiRender, ARankWithAnotherSceneIsRefused) {
    test::TempDir dir;
    const auto out = dir / "out.pfm";
    // Rank 2 is given another field of view, as a host with another copy of the scene file would be.
    const auto r = test::run_command(
        mpirun(3) +
        "sh -c 'if [ \"$OMPI_COMM_WORLD_RANK\" = 2 ]; then exec \"$0\" \"$@\" --set camera.fov=30; "
        "else exec \"$0\" \"$@\"; fi' " +
        kGlint + " render '" + kScene + "'" + kSize + "-o " + quoted(out));
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("rank 2 on "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("built another scene than rank 0"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(MpiRender, ARankThatDiesFailsTheRunWithoutHanging) {
    test::TempDir dir;
    const auto out = dir / "out.pfm";
    // Rank 2 is killed a second into a render of several seconds; the others are waiting for its band
    // or about to hand it another. `timeout` turns a hang into a failure of this test.
    const auto start = std::chrono::steady_clock::now();
    const auto r = test::run_command(
        mpirun(3, "timeout 120 ") +
        "sh -c 'if [ \"$OMPI_COMM_WORLD_RANK\" = 2 ]; then \"$0\" \"$@\" & sleep 1; kill -KILL $!; exit 137; "
        "else exec \"$0\" \"$@\"; fi' " +
        kGlint + " render '" + kScene + "' --width 320 --height 180 --spp 64 --quiet -o " + quoted(out));
    // mpirun exits with the status of the first rank to fail: that of the killed one (timeout's 124 would
    // be a hang).
    EXPECT_EQ(r.exit_code, 137) << r.output;
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(60)) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out));
}

TEST(MpiRender, TileAndTimeLimitAreRefusedUnderMpirun) {
    test::TempDir dir;
    for (const std::string& flags :
         {"--tile 0/2 -o " + quoted(dir / "p.exr"), "--time-limit 5 -o " + quoted(dir / "p.exr")}) {
        const auto r = test::run_command(mpirun(2) + kGlint + " render '" + kScene + "'" + kSize + flags);
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_EQ(occurrences(r.output, "under mpirun"), 1u) << r.output;
        EXPECT_FALSE(std::filesystem::exists(dir / "p.exr"));
    }
}
#endif

}  // namespace
}  // namespace glint
