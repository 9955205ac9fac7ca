// Lights as the scene builder makes them: area lights add their shape, the environment replaces the
// background, and bad values are positioned errors.
#include <gtest/gtest.h>

#include "glint/light/area.hpp"
#include "glint/params/diagnostics.hpp"
#include "integrator/radiance_util.hpp"

namespace glint {
namespace {

using test::scene_from_yaml;

std::string error_of(const std::string& yaml) {
    try {
        scene_from_yaml(yaml);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

TEST(LightScene, AnAreaLightAddsItsShapeAndTheCameraSeesItsRadiance) {
    const Scene scene = scene_from_yaml(R"(
render: {width: 4, height: 4, samples: 1, integrator: path}
camera: {eye: [0, 0, 5], look_at: [0, 0, 0], fov: 10}
objects: [{type: plane, point: [0, 0, -3], normal: [0, 0, 1]}]
lights: [{type: area, radiance: [1, 2, 3], shape: {type: disk, center: [0, 0, 0], normal: [0, 0, 1], radius: 2}}]
)");
    ASSERT_EQ(scene.world->shapes.size(), 2u);
    EXPECT_EQ(scene.world->shape_lights[0], -1);
    EXPECT_EQ(scene.world->shape_lights[1], 0);
    const Film film = test::render_film(scene);
    EXPECT_EQ(film.pixel(1, 2), Rgb(1, 2, 3));  // the front face, head-on
}

TEST(LightScene, AnEmissiveObjectIsAnAreaLight) {
    // A sphere of radiance L and radius R, its centre a height d above a matte floor of albedo ρ: the
    // floor point below it receives E = π L (R/d)² and shows ρ/π · E = ρ L (R/d)².
    for (const char* integrator : {"raycast", "path"}) {
        const Scene scene = scene_from_yaml(std::string(R"(
render: {width: 8, height: 8, samples: 16, max_depth: 1, integrator: )") +
                                            integrator + R"(}
camera: {eye: [3, 0.5, 0], look_at: [0, 0, 0], fov: 0.05}
objects:
  - {type: plane, normal: [0, 1, 0], material: {type: matte, albedo: 0.5}}
  - {type: sphere, center: [0, 2, 0], radius: 0.5, material: {type: emissive, radiance: 4}}
)");
        ASSERT_EQ(scene.world->lights.size(), 1u);
        EXPECT_EQ(scene.world->shape_lights[1], 0);
        EXPECT_NE(dynamic_cast<const AreaLight*>(scene.world->lights[0].get()), nullptr);
        const test::RegionMean m = test::region_mean(test::render_film(scene), 0, 0, 8, 8);
        EXPECT_NEAR(m.mean, 0.5 * 4 * (0.25 / 4), 4 * m.standard_error + 1e-3) << integrator;
    }
}

TEST(LightScene, OneSidedEmittersAreDarkFromBehind) {
    const Scene scene = scene_from_yaml(R"(
render: {width: 2, height: 2, samples: 1, integrator: raycast}
camera: {eye: [0, 0, -5], look_at: [0, 0, 0], fov: 10}
lights: [{type: area, radiance: 5, shape: {type: disk, normal: [0, 0, 1], radius: 2}}]
)");
    EXPECT_EQ(test::render_film(scene).pixel(0, 0), Rgb(0.0));
}

TEST(LightScene, TheEnvironmentIsTheBackground) {
    const Scene scene = scene_from_yaml(R"(
render: {width: 2, height: 2, samples: 1}
lights: [{type: environment, radiance: [0.1, 0.2, 0.3], scale: 2}]
)");
    ASSERT_NE(scene.world->environment, nullptr);
    const Rgb sky = test::render_film(scene).pixel(1, 1);
    EXPECT_NEAR(sky.b, 0.6, 1e-15);
}

TEST(LightScene, MistakesArePositionedErrors) {
    EXPECT_NE(
        error_of("background: 1\nlights: [{type: environment}]").find("remove the scene's `background`"),
        std::string::npos);
    EXPECT_NE(error_of("lights: [{type: environment}, {type: environment}]").find("at most one environment"),
              std::string::npos);
    EXPECT_NE(error_of("lights: [{type: area, shape: {type: plane, normal: [0, 1, 0]}}]")
                  .find("finite, non-zero area"),
              std::string::npos);
    EXPECT_NE(error_of("lights: [{type: area, radiance: 1}]").find("shape"), std::string::npos);
    EXPECT_NE(error_of("lights: [{type: area, shape: {type: sphere, radius: 1, colour: 2}}]").find("colour"),
              std::string::npos);
    EXPECT_NE(error_of("lights: [{type: spot, position: [0, 1, 0], angle: 20, falloff_angle: 30}]")
                  .find("falloff_angle"),
              std::string::npos);
    EXPECT_NE(error_of("lights: [{type: spot, position: [0, 1, 0], look_at: [0, 1, 0]}]").find("look_at"),
              std::string::npos);
    EXPECT_NE(error_of("lights: [{type: directional, direction: [0, 0, 0]}]").find("direction"),
              std::string::npos);
    EXPECT_NE(error_of("lights: [{type: environment, image: sky.png}]").find(".exr or .pfm"),
              std::string::npos);
    EXPECT_NE(error_of("lights: [{type: environment, image: missing.pfm}]").find("cannot read"),
              std::string::npos);
    EXPECT_NE(
        error_of("lights: [{type: environment, radiance: {type: gradient, top: 1, botom: 0}}]").find("botom"),
        std::string::npos);
    EXPECT_NE(error_of("lights: [{type: ambient-occlusion, samples: 0}]").find("samples"), std::string::npos);
    EXPECT_NE(error_of("lights: [{type: sport}]").find("did you mean 'spot'"), std::string::npos);
    EXPECT_NE(error_of("render: {integrator: paht}").find("did you mean 'path'"), std::string::npos);
}

}  // namespace
}  // namespace glint
