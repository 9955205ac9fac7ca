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
const std::string kBunny = std::string(GLINT_SOURCE_DIR) + "/examples/bunny.yaml";

TEST(InfoCommand, CountsTheBunnysTrianglesAndDescribesTheBvh) {
    std::string out;
    ASSERT_EQ(run(kCli + " info " + kBunny, out), 0) << out;
    EXPECT_NE(out.find("triangles    69451"), std::string::npos) << out;  // the OBJ's own header count
    EXPECT_NE(out.find("primitives   2 (1 meshes"), std::string::npos) << out;
    EXPECT_NE(out.find("bvh nodes"), std::string::npos) << out;
    EXPECT_NE(out.find("bytes"), std::string::npos) << out;
    // The bunny's box as the Stanford repository's file gives it (the floor plane is left out): the
    // scene tree holds no shape here (a lone mesh is tested directly), and the box must still show.
    EXPECT_NE(out.find("bounds       (bounded shapes) [-0.09469, 0.032987, -0.061874] .. "
                       "[0.061009, 0.187321, 0.0588]"),
              std::string::npos)
        << out;
}

TEST(InfoCommand, BadSceneIsExitCode2) {
    std::string out;
    EXPECT_EQ(run(kCli + " info /nonexistent/scene.yaml", out), 2) << out;
    EXPECT_EQ(run(kCli + " render --accel nope -q -o /dev/null.png " + kBunny, out), 2) << out;
    EXPECT_NE(out.find("unknown accelerator 'nope'"), std::string::npos) << out;
}

}  // namespace
