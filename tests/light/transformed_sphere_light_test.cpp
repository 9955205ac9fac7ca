// A sphere light placed by a `transform` is sampled like one placed by its centre (glint issue 12): by
// the cone it subtends, so the floor beneath it is as smooth, and the light it sends is the analytic
// irradiance of a sphere.
#include <gtest/gtest.h>

#include "glint/light/area.hpp"
#include "integrator/radiance_util.hpp"

namespace glint {
namespace {

using test::scene_from_yaml;

// A matte floor of albedo 0.5 under a sphere light of radiance 4 and radius 0.5, written by `sphere`
// (its centre, and perhaps a transform), seen through a camera so narrow that every pixel shows the
// floor point below the light's centre.
Film floor_under(const std::string& sphere, const std::string& integrator) {
    const Scene scene = scene_from_yaml(R"(
render: {width: 24, height: 24, samples: 4, max_depth: 1, integrator: )" +
                                        integrator + R"(}
camera: {eye: [3, 0.5, 0], look_at: [0, 0, 0], fov: 0.05}
objects:
  - {type: plane, normal: [0, 1, 0], material: {type: matte, albedo: 0.5}}
  - {type: sphere, )" + sphere + R"(, material: {type: emissive, radiance: 4}}
)");
    EXPECT_EQ(scene.lights.size(), 1u);
    return test::render_film(scene);
}

TEST(TransformedSphereLight, IsAsSmoothAsTheSameLightWithoutTransform) {
    // Every pixel sees (nearly) the same floor point, so each is an independent estimate of its
    // radiance and the spread of the pixels is the per-pixel noise. Sampled by area instead of by its
    // cone, a transformed sphere light put half its samples on its far side and spread the rest over a
    // wide range of solid-angle densities: here that made the spread 57–232× larger (raycast ~200×,
    // path ~60×, since its BSDF samples, weighted by MIS, also find the light).
    const double expected = 0.5 * 4 * (0.25 / 4);  // ρ L (R/d)², as in LightScene.AnEmissiveObject…
    for (const char* integrator : {"raycast", "path"}) {
        const test::RegionMean plain =
            test::region_mean(floor_under("center: [0, 2, 0], radius: 0.5", integrator), 0, 0, 24, 24);
        EXPECT_GT(plain.standard_error, 0) << integrator;
        EXPECT_NEAR(plain.mean, expected, 4 * plain.standard_error) << integrator;
        for (const char* sphere :
             {"radius: 0.5, transform: {translate: [0, 2, 0]}",
              "radius: 2, transform: {scale: 0.25, rotate: {axis: [1, 2, 3], angle: 70}, "
              "translate: [0, 2, 0]}"}) {
            const test::RegionMean placed = test::region_mean(floor_under(sphere, integrator), 0, 0, 24, 24);
            EXPECT_LT(placed.standard_error, 1.5 * plain.standard_error) << integrator << ", " << sphere;
            EXPECT_GT(placed.standard_error, plain.standard_error / 1.5) << integrator << ", " << sphere;
            EXPECT_NEAR(placed.mean, expected, 4 * placed.standard_error) << integrator << ", " << sphere;
        }
    }
}

}  // namespace
}  // namespace glint
