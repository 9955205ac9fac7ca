// `glint info` and `glint render --accel` through the real binary.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace {

// Runs a command; returns its exit code and fills `out` with its standard output.
int run(const std::string& command, std::string& out) {
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (pipe == nullptr) {
        return -1;
    }
    char buffer[4096];
    out.clear();
    while (std::fgets(buffer, sizeof(buffer), pipe) != nullptr) {
        out += buffer;
    }
    const int status = pclose(pipe);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

const std::string kCli = GLINT_CLI_PATH;
const std::string kKnot = std::string(GLINT_SOURCE_DIR) + "/examples/knot.yaml";

TEST(InfoCommand, CountsTheKnotsTrianglesAndDescribesTheBvh) {
    std::string out;
    ASSERT_EQ(run(kCli + " info " + kKnot, out), 0) << out;
    // scripts/make_knot_mesh.py: 256 rings of 24 vertices, two triangles per quad between rings.
    EXPECT_NE(out.find("triangles    12288 (6144 vertices)"), std::string::npos) << out;
    EXPECT_NE(out.find("primitives   2 (1 meshes"), std::string::npos) << out;
    EXPECT_NE(out.find("bvh nodes"), std::string::npos) << out;
    EXPECT_NE(out.find("bytes"), std::string::npos) << out;
    // The floor plane is left out of the box, which must still show. The knot's curve has z = −sin 3t in
    // [−1, 1], where its tangent is level, so its tube of radius 0.35 reaches 1.35 ± the facets' sag
    // (0.35 (1 − cos(π/24)) < 0.003); the example turns it by −90° about x, so that is its height.
    const auto at = out.find("bounds       (bounded shapes) [");
    ASSERT_NE(at, std::string::npos) << out;
    double lo[3], hi[3];
    ASSERT_EQ(
        std::sscanf(out.c_str() + at, "bounds       (bounded shapes) [%lf, %lf, %lf] .. [%lf, %lf, %lf]",
                    &lo[0], &lo[1], &lo[2], &hi[0], &hi[1], &hi[2]),
        6)
        << out;
    EXPECT_NEAR(lo[1], -1.35, 0.003);
    EXPECT_NEAR(hi[1], 1.35, 0.003);
}

TEST(InfoCommand, BadSceneIsExitCode2) {
    std::string out;
    EXPECT_EQ(run(kCli + " info /nonexistent/scene.yaml", out), 2) << out;
    EXPECT_EQ(run(kCli + " render --accel nope -q -o /tmp/never.png " + kKnot, out), 2) << out;
    EXPECT_NE(out.find("unknown accelerator 'nope'"), std::string::npos) << out;
}

}  // namespace
