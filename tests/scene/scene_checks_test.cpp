// The warnings of scenes that would render black without a word (issue 15): each on its own scene,
// none on the examples.
#include <gtest/gtest.h>

#include "glint/scene/scene_checks.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

bool warns(const std::string& yaml, const std::string& part) {
    for (const std::string& warning : scene_warnings(test::scene_from_text(yaml))) {
        if (warning.find(part) != std::string::npos) {
            return true;
        }
    }
    return false;
}

TEST(SceneChecks, ASceneWithoutLightIsNamed) {
    EXPECT_TRUE(warns("objects:\n  - {type: sphere, radius: 1}\n", "the scene has no light"));
    EXPECT_FALSE(warns("objects:\n  - {type: sphere, radius: 1}\nlights:\n  - {type: ambient, radiance: 1}\n",
                       "no light"));
    EXPECT_FALSE(warns("background: [0.2, 0.3, 0.4]\nobjects:\n  - {type: sphere, radius: 1}\n", "no light"));
    EXPECT_FALSE(warns("objects:\n  - {type: sphere, radius: 1, material: {type: emissive}}\n", "no light"));
}

TEST(SceneChecks, MirrorsUnderRaycastAreNamedWithTheFix) {
    const std::string scene =
        "objects:\n  - {type: sphere, radius: 1, material: {type: mirror}}\nlights:\n"
        "  - {type: point, position: [0, 3, 3], intensity: 10}\n";
    EXPECT_TRUE(warns(scene, "--integrator whitted"));
    EXPECT_FALSE(warns("render: {integrator: whitted}\n" + scene, "mirror"));
    EXPECT_FALSE(warns("render: {integrator: path}\n" + scene, "mirror"));
    // A glossy metal is not a mirror: raycast lights it.
    EXPECT_FALSE(
        warns("objects:\n  - {type: sphere, radius: 1, material: {type: metal, roughness: 0.3}}\n"
              "lights:\n  - {type: point, position: [0, 3, 3], intensity: 10}\n",
              "mirror"));
}

TEST(SceneChecks, PointLightsUnseenByAPathWithoutLightSamplingAreNamed) {
    const std::string objects = "objects:\n  - {type: sphere, radius: 1}\n";
    const std::string point = "lights:\n  - {type: point, position: [0, 3, 3], intensity: 10}\n";
    const std::string off = "render: {integrator: {type: path, sample_lights: false}}\n";
    EXPECT_TRUE(warns(off + objects + point, "sample_lights: false"));
    EXPECT_FALSE(warns("render: {integrator: path}\n" + objects + point, "sample_lights"));
    // Light that its BSDF samples can find: an emitter, an environment, a background.
    EXPECT_FALSE(warns(
        off + objects + point + "  - {type: area, shape: {type: sphere, center: [0, 5, 0], radius: 1}}\n",
        "sample_lights"));
    EXPECT_FALSE(warns(off + objects + point + "  - {type: environment, radiance: 0.5}\n", "sample_lights"));
    EXPECT_FALSE(warns(off + "background: [0.2, 0.3, 0.4]\n" + objects + point, "sample_lights"));
}

TEST(SceneChecks, TheExamplesGetNoWarning) {
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(GLINT_SOURCE_DIR) / "examples")) {
        if (entry.path().extension() != ".yaml") {
            continue;
        }
        const Scene scene = build_scene(load_scene_file(entry.path()));
        EXPECT_TRUE(scene_warnings(scene).empty()) << entry.path() << ": " << scene_warnings(scene).front();
    }
}

TEST(SceneChecks, AnAllBlackImageIsSaidAfterTheRender) {
    test::TempDir dir;
    dir.write("dark.yaml",
              "render: {width: 4, height: 4, samples: 1}\nobjects:\n  - {type: sphere, radius: 1}\n");
    const auto result = test::run_glint("render '" + (dir / "dark.yaml").string() + "' -o '" +
                                        (dir / "dark.png").string() + "' -q");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("warning: the scene has no light"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("warning: every pixel of the image is black"), std::string::npos)
        << result.output;
}

}  // namespace
}  // namespace glint
