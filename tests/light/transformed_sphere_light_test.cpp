// A sphere light placed by a `transform` is sampled like one placed by its centre (glint issue 12): by
// the cone it subtends, so the floor beneath it is as smooth, and the light it sends is the analytic
// irradiance of a sphere.
#include <gtest/gtest.h>

#include "glint/core/hash.hpp"
#include "glint/geometry/instance.hpp"
#include "glint/geometry/sphere.hpp"
#include "glint/light/area.hpp"
#include "integrator/radiance_util.hpp"

namespace glint {
namespace {

using test::scene_from_yaml;

// A matte floor of albedo 0.5 under a sphere light of radiance 4, written by `sphere` (its radius, its
// centre or a transform), seen through a camera so narrow that every pixel shows the same floor point,
// the origin.
Film floor_under(const std::string& sphere, const std::string& integrator, int samples = 4) {
    const Scene scene = scene_from_yaml(R"(
render: {width: 24, height: 24, samples: )" +
                                        std::to_string(samples) +
                                        ", max_depth: 1, integrator: " + integrator + R"(}
camera: {eye: [3, 0.5, 0], look_at: [0, 0, 0], fov: 0.05}
objects:
  - {type: plane, normal: [0, 1, 0], material: {type: matte, albedo: 0.5}}
  - {type: sphere, )" + sphere + R"(, material: {type: emissive, radiance: 4}}
)");
    EXPECT_EQ(scene.world->lights.size(), 1u);
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

// The irradiance at a point from a sphere of radiance L whose centre is d away, at angle α to the
// point's normal, with the whole sphere above the horizon (θ + α ≤ π/2, sin θ = R/d): π L sin²θ cos α.
// (The sphere's cone projects onto the tangent plane as a disk-shaped form factor: Nusselt's analogue.)
double sphere_irradiance(double radiance, double radius, const Vec3& to_center, const Vec3& normal) {
    const double d = length(to_center);
    return kPi * radiance * sqr(radius / d) * dot(to_center, normal) / d;
}

TEST(TransformedSphereLight, SendsTheAnalyticIrradiance) {
    // E = ∫ L cos θ dω, estimated from the light's own samples: Σ L cos θ / pdf / N.
    const Vec3 center{1, 2, 0.5};
    const Vec3 normal{0, 1, 0};
    struct Placed {
        double radius;
        Transform transform;
        const char* what;
    };
    for (const Placed& placed : {Placed{0.5, Transform::translate(center), "translated"},
                                 Placed{0.2,
                                        Transform::scale(Vec3{2.5, 2.5, 2.5})
                                            ->then(Transform::rotate({1, 0, 2}, 120))
                                            .then(Transform::translate(center)),
                                        "scaled, rotated and translated"}}) {
        const Instance sphere(std::make_unique<Sphere>(Vec3{}, placed.radius), placed.transform);
        const AreaEmitter emitter(Rgb(3.0), false);
        const AreaLight light(sphere, emitter, 1);
        Hit at;
        at.point = {0, 0, 0};
        at.normal = at.shading_normal = normal;
        constexpr int kSamples = 100000;
        double sum = 0, sum_squares = 0;
        for (std::uint32_t i = 0; i < kSamples; ++i) {
            const SampleKey key{77, i, 0, 0};
            const std::optional<LightSample> s = light.sample(at, {key.uniform(0), key.uniform(1)});
            ASSERT_TRUE(s) << placed.what;  // every sample of the cone lands on the near, emitting side
            const double e = s->radiance.g * dot(normal, s->wi) / s->pdf;
            sum += e;
            sum_squares += e * e;
        }
        const double mean = sum / kSamples;
        const double standard_error = std::sqrt((sum_squares / kSamples - mean * mean) / (kSamples - 1));
        const double expected = sphere_irradiance(3.0, 0.5, center - at.point, normal);
        EXPECT_LT(standard_error, 1e-3 * expected);
        EXPECT_NEAR(mean, expected, 4 * standard_error) << placed.what;
    }
}

TEST(TransformedSphereLight, RendersTheAnalyticIrradiance) {
    // The same sphere light, off to the side of the floor point the camera sees: the matte floor of
    // albedo ρ shows ρ/π · E, with both integrators (the path tracer weighs its BSDF samples that hit the
    // light against the light's pdf).
    const double expected = 0.5 / kPi * sphere_irradiance(4.0, 0.5, {1, 2, 0.5}, {0, 1, 0});
    for (const char* integrator : {"raycast", "path"}) {
        for (const char* sphere : {"radius: 0.5, transform: {translate: [1, 2, 0.5]}",
                                   "radius: 0.2, transform: {scale: 2.5, rotate: {axis: [1, 0, 2], angle: "
                                   "120}, translate: [1, 2, 0.5]}"}) {
            const test::RegionMean m = test::region_mean(floor_under(sphere, integrator, 16), 0, 0, 24, 24);
            EXPECT_LT(m.standard_error, 1e-3 * expected) << integrator << ", " << sphere;
            EXPECT_NEAR(m.mean, expected, 4 * m.standard_error) << integrator << ", " << sphere;
        }
    }
}

}  // namespace
}  // namespace glint
