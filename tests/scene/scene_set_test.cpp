// `--set key.path=value`: every key of the file can be set from the command line, and is checked, with
// the same messages, as the file's.
#include "glint/scene/scene_set.hpp"

#include <gtest/gtest.h>

#include "test_util.hpp"

namespace glint {
namespace {

const std::string kScene =
    "render: {width: 32, height: 24, samples: 16, integrator: path}\n"
    "camera: {eye: [0, 1, 4], look_at: [0, 0, 0], fov: 50}\n"
    "objects:\n"
    "  - {type: sphere, center: [0, 0, 0], radius: 1}\n"
    "lights: [{type: point, position: [2, 4, 2], intensity: 20}]\n";

Scene built_with(const std::string& text, const std::vector<std::string>& sets) {
    SceneDesc desc = parse_scene_text(text, "scene.yaml", ".");
    for (const std::string& set : sets) {
        apply_set(desc, set);
    }
    return build_scene(desc);
}

SceneError error_with(const std::string& text, const std::vector<std::string>& sets) {
    try {
        built_with(text, sets);
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "no error";
    return SceneError({}, "");
}

// The ray through the image centre and a corner: cameras that agree on these agree.
std::pair<Ray, Ray> camera_rays(const Scene& scene) {
    return {scene.view.camera->generate_ray({16, 12}, {0.5, 0.5}),
            scene.view.camera->generate_ray({0, 0}, {0.5, 0.5})};
}

TEST(SceneSet, SetsRenderAndCameraKeysAsTheFileWould) {
    const Scene set = built_with(kScene, {"render.samples=4", "camera.fov=30"});
    std::string edited = kScene;
    edited.replace(edited.find("samples: 16"), 11, "samples: 4");
    edited.replace(edited.find("fov: 50"), 7, "fov: 30");
    const Scene file = build_scene(parse_scene_text(edited, "scene.yaml", "."));
    EXPECT_EQ(set.view.settings.samples_per_pixel, 4u);
    EXPECT_EQ(set.view.sampler->samples_per_pixel(), 4u);
    const auto [centre, corner] = camera_rays(set);
    const auto [file_centre, file_corner] = camera_rays(file);
    EXPECT_EQ(corner.direction, file_corner.direction);
    EXPECT_EQ(centre.direction, file_centre.direction);
    EXPECT_NE(corner.direction, camera_rays(built_with(kScene, {})).second.direction);  // fov changed
}

TEST(SceneSet, AMisspeltKeyGetsTheFilesDidYouMeanPointingAtTheArgument) {
    const SceneError set = error_with(kScene, {"render.samplse=4"});
    EXPECT_NE(set.message().find("did you mean 'samples'"), std::string::npos) << set.what();
    EXPECT_EQ(set.position().file->path, "--set");
    EXPECT_EQ(set.position().column, 8);  // at `samplse`
    EXPECT_NE(std::string(set.what()).find("render.samplse=4"), std::string::npos) << set.what();
    // The same message as the same mistake in the file.
    std::string misspelt = kScene;
    misspelt.replace(misspelt.find("samples: 16"), 7, "samplse");
    try {
        build_scene(parse_scene_text(misspelt, "scene.yaml", "."));
        ADD_FAILURE() << "no error";
    } catch (const SceneError& file) {
        EXPECT_EQ(file.message(), set.message());
    }
}

TEST(SceneSet, AValueIsCheckedWhereItWasGiven) {
    const SceneError e = error_with(kScene, {"render.width=-3"});
    EXPECT_EQ(e.position().file->path, "--set");
    EXPECT_EQ(e.position().column, 14);  // at the value
    EXPECT_NE(e.message().find("render.width"), std::string::npos) << e.what();
}

TEST(SceneSet, IntegratorKeysExpandTheShortForm) {
    const Scene deep = built_with(kScene, {"render.integrator.max_depth=8"});
    EXPECT_EQ(deep.view.settings.integrator, "path");
    // raycast follows no bounces: max_depth is not one of its keys.
    const SceneError e = error_with(kScene, {"render.integrator=raycast", "render.integrator.max_depth=8"});
    EXPECT_NE(e.message().find("unknown key 'max_depth' in raycast integrator"), std::string::npos)
        << e.what();
    // A whole map as the value.
    const Scene whole = built_with(kScene, {"render.integrator={type: whitted, max_depth: 3}"});
    EXPECT_EQ(whole.view.settings.integrator, "whitted");
}

TEST(SceneSet, ListElementsAndNewMapsAlongThePath) {
    const Scene bigger = built_with(kScene, {"objects.0.radius=2"});
    EXPECT_GT(bigger.world->shapes[0]->area(), built_with(kScene, {}).world->shapes[0]->area() * 3.9);
    const Scene grey = built_with(kScene, {"background=[0.5, 0.5, 0.5]", "materials.red.type=matte"});
    EXPECT_EQ(grey.world->background.g, 0.5);
    const SceneError past = error_with(kScene, {"objects.1.radius=2"});
    EXPECT_NE(past.message().find("not an element of this list of 1"), std::string::npos) << past.what();
    const SceneError through = error_with(kScene, {"render.width.x=1"});
    EXPECT_NE(through.message().find("not a map"), std::string::npos) << through.what();
    const SceneError malformed = error_with(kScene, {"render.samples"});
    EXPECT_NE(malformed.message().find("key.path=value"), std::string::npos) << malformed.what();
    const SceneError empty = error_with(kScene, {"render..samples=3"});
    EXPECT_EQ(empty.position().column, 8);
}

TEST(SceneSet, BuildSceneAppliesTheFlagsThenEachSetInOrder) {
    RenderFlags flags;
    flags.width = 8;
    flags.samples_per_pixel = 2;
    const std::vector<std::string> sets = {"render.width=6", "render.height=5", "render.width=4"};
    const Scene scene = build_scene(parse_scene_text(kScene, "scene.yaml", "."), flags, sets);
    EXPECT_EQ(scene.view.settings.width, 4);   // the last set wins over the flag and the earlier set
    EXPECT_EQ(scene.view.settings.height, 5);  // a set alone
    EXPECT_EQ(scene.view.settings.samples_per_pixel, 2u);  // a flag alone
    const std::vector<std::string> misspelt = {"render.samplse=4"};
    EXPECT_THROW(build_scene(parse_scene_text(kScene, "scene.yaml", "."), {}, misspelt), SceneError);
}

TEST(SceneSet, TheCommandLineTakesSetAndReportsItsMistakesWithExitCode2) {
    test::TempDir dir;
    const auto scene = dir.write("scene.yaml", kScene);
    const auto ok =
        test::run_glint("render -q '" + scene.string() + "' --set render.samples=4 --set camera.fov=30 -o '" +
                        (dir / "out.png").string() + "'");
    EXPECT_EQ(ok.exit_code, 0) << ok.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "out.png"));
    const auto bad = test::run_glint("render -q '" + scene.string() + "' --set render.samplse=4 -o '" +
                                     (dir / "bad.png").string() + "'");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.output.find("--set:1:8: error: unknown key 'samplse' in render; did you mean 'samples'?"),
              std::string::npos)
        << bad.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.png"));
}

}  // namespace
}  // namespace glint
