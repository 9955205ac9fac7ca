// LightVisibility: the cap of a sphere light that the view sees, learnt before rendering, against values
// known without the code: the cap a ceiling plane cuts off a sphere, the irradiance under it, and the
// solid angle the mixture's density must integrate to.
#include <gtest/gtest.h>

#include <cmath>

#include "glint/core/hash.hpp"
#include "glint/integrator/light_visibility.hpp"
#include "glint/integrator/path.hpp"
#include "glint/render/progressive.hpp"
#include "integrator/radiance_util.hpp"

namespace glint {
namespace {

using test::region_mean;
using test::render_film;
using test::scene_from_yaml;

// A sphere light of radius R = 100 buried in a black ceiling at height H = 40 but for a cap δ = 0.25
// deep (smallpt's light in miniature: from the floor the cone towards the sphere is 46° wide, the cap in
// sight 10°), over a matte floor of albedo ρ = 0.5. The camera, at height 5, looks straight down at the
// origin through a 1° field, so every pixel sees the floor within 0.05 of it.
constexpr double kRadius = 100;
constexpr double kCeiling = 40;
constexpr double kDepth = 0.25;
constexpr double kAlbedo = 0.5;
constexpr double kRadiance = 4;

std::string buried_light_scene(const std::string& integrator) {
    return R"(
render: {width: 16, height: 16, samples: 64, integrator: )" +
           integrator + R"(, max_depth: 2}
camera: {type: pinhole, eye: [0, 5, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 1}
objects:
  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, albedo: [0.5, 0.5, 0.5]}}
  - {type: plane, point: [0, 40, 0], normal: [0, -1, 0], material: {type: matte, albedo: [0, 0, 0]}}
lights:
  - {type: area, radiance: [4, 4, 4], shape: {type: sphere, center: [0, 139.75, 0], radius: 100}}
)";
}

const PathIntegrator& path_integrator(const ProgressiveRender& render) {
    return dynamic_cast<const PathIntegrator&>(render.integrator());
}

TEST(LightVisibility, LearnsTheCapThatTheCeilingLeavesInSight) {
    const Scene scene = scene_from_yaml(buried_light_scene("path"));
    const ProgressiveRender render(*scene.world, scene.view);
    const LightVisibility* visibility = path_integrator(render).light_visibility();
    ASSERT_NE(visibility, nullptr);
    const SphereCap* cap = visibility->cap(0);
    ASSERT_NE(cap, nullptr);
    // The seen part is the sphere below the ceiling: normals within acos((R − δ)/R) = 4.05° of −y.
    EXPECT_NEAR(cap->frame.n.y, -1, 1e-4);
    const double seen_angle = std::acos((kRadius - kDepth) / kRadius);
    const double cap_angle = std::acos(cap->cos_max);
    EXPECT_GT(cap_angle, 0.9 * seen_angle);
    EXPECT_LT(cap_angle, 1.1 * seen_angle);
    EXPECT_LT(cap->seen, cap->traced / 2);  // the cone wasted more than half: why the cap is used
    EXPECT_GE(cap->seen, 32u);
}

TEST(LightVisibility, NothingIsLearntForALightInFullViewOrWhenSwitchedOff) {
    // Without the ceiling, the view sees the whole lower half of the sphere: no cap.
    Scene open = scene_from_yaml(R"(
render: {width: 16, height: 16, samples: 1, integrator: path}
camera: {type: pinhole, eye: [0, 5, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 60}
objects:
  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, albedo: [0.5, 0.5, 0.5]}}
lights:
  - {type: area, radiance: [4, 4, 4], shape: {type: sphere, center: [0, 20, 0], radius: 2}}
)");
    const ProgressiveRender open_render(*open.world, open.view);
    EXPECT_EQ(path_integrator(open_render).light_visibility(), nullptr);

    const Scene off = scene_from_yaml(buried_light_scene("{type: path, learn_light_visibility: false}"));
    const ProgressiveRender off_render(*off.world, off.view);
    EXPECT_EQ(path_integrator(off_render).light_visibility(), nullptr);
}

TEST(LightVisibility, TheFloorUnderTheCapGetsTheIrradianceOfItsRimDisk) {
    // From the floor under the axis, the cap's silhouette is its rim, a disk of radius a
    // (a² = 2Rδ − δ²) at height H: a Lambertian emitter of radiance L gives E = π L a² / (a² + H²),
    // so the floor reflects ρ/π · E = ρ L a² / (a² + H²). The ceiling is black and the light's own
    // surface reflects nothing, so that is all the light there is.
    const double a2 = 2 * kRadius * kDepth - kDepth * kDepth;
    const double expected = kAlbedo * kRadiance * a2 / (a2 + kCeiling * kCeiling);
    for (const char* integrator : {"path", "{type: path, learn_light_visibility: false}"}) {
        const Scene scene = scene_from_yaml(buried_light_scene(integrator));
        const Film film = render_film(scene);
        const test::RegionMean mean = region_mean(film, 0, 0, 16, 16, 1);
        EXPECT_NEAR(mean.mean, expected, 5 * mean.standard_error + 1e-3 * expected) << integrator;
    }
}

TEST(LightVisibility, TheCapHalvesTheNoiseUnderIt) {
    // The same floor with and without the cap, each pixel an independent estimate of one value: the
    // cone sends most shadow rays into the ceiling, the cap almost none.
    const auto noise = [](const char* integrator) {
        Scene scene = scene_from_yaml(buried_light_scene(integrator));
        scene.view.settings.samples_per_pixel = 4;
        scene.view.sampler = make_sampler("sobol", 4);
        return region_mean(render_film(scene), 0, 0, 16, 16, 1).standard_error;
    };
    EXPECT_LT(noise("path"), 0.5 * noise("{type: path, learn_light_visibility: false}"));
}

TEST(LightVisibility, TheMixtureDensityIntegratesToTheSolidAnglesAndMatchesPdf) {
    // E[1{X ∈ S} / p(X)] over the directions X drawn from the mixture (those that reach the sphere's
    // near side) is the solid angle of S. For S the whole cone the sphere subtends, 2π (1 − cos θ_max);
    // for S the directions to the cap below the ceiling, seen from under its axis, the cone of its rim:
    // 2π (1 − H / √(H² + a²)). A density too small or too large anywhere (or pdf() disagreeing with
    // sample()) moves one of them.
    const Scene scene = scene_from_yaml(buried_light_scene("path"));
    const ProgressiveRender render(*scene.world, scene.view);
    const LightVisibility* visibility = path_integrator(render).light_visibility();
    ASSERT_NE(visibility, nullptr);
    const Light& light = *scene.world->lights[0];
    const Vec3 center{0, kCeiling + kRadius - kDepth, 0};

    struct Estimate {
        double mean, standard_error;
    };
    // The mean of 1{in_region(point)} / pdf over n samples from `at`.
    const auto integrate = [&](const Vec3& point, auto in_region) {
        Hit at;
        at.point = point;
        at.normal = at.shading_normal = {0, 1, 0};
        const int n = 200000;
        double sum = 0, sum2 = 0;
        for (int i = 0; i < n; ++i) {
            const Point2 u = unit_pair(hash_values(7, static_cast<std::uint64_t>(i)));
            const std::optional<LightSample> ls = visibility->sample(0, light, at, u);
            if (!ls) {
                continue;
            }
            // pdf() of the same direction, from the point the direction meets first.
            Hit on_light;
            on_light.point = ls->position;
            on_light.normal = on_light.shading_normal = normalize(ls->position - center);
            EXPECT_NEAR(visibility->pdf(0, light, at, ls->wi, &on_light), ls->pdf, 1e-9 * ls->pdf);
            const double w = in_region(ls->position) ? 1 / ls->pdf : 0;
            sum += w;
            sum2 += w * w;
        }
        const double mean = sum / n;
        return Estimate{mean, std::sqrt((sum2 / n - mean * mean) / n)};
    };

    const Vec3 off_axis{3, 0, -2};
    const double sin2_max = kRadius * kRadius / length_squared(center - off_axis);
    const double cone = 2 * kPi * (1 - std::sqrt(1 - sin2_max));
    const Estimate whole = integrate(off_axis, [](const Vec3&) { return true; });
    EXPECT_NEAR(whole.mean, cone, 5 * whole.standard_error);
    EXPECT_LT(whole.standard_error, 0.01 * cone);

    const double a2 = 2 * kRadius * kDepth - kDepth * kDepth;
    const double rim = 2 * kPi * (1 - kCeiling / std::sqrt(kCeiling * kCeiling + a2));
    const Estimate below = integrate(Vec3{0, 0, 0}, [](const Vec3& p) { return p.y < kCeiling; });
    EXPECT_NEAR(below.mean, rim, 5 * below.standard_error);
    EXPECT_LT(below.standard_error, 0.005 * rim);
}

TEST(LightVisibility, TheImageIsTheSameForAnyThreadsAndTiles) {
    Scene a = scene_from_yaml(buried_light_scene("path"));
    a.view.settings.samples_per_pixel = 3;
    a.view.sampler = make_sampler("sobol", 3);
    Scene b = scene_from_yaml(buried_light_scene("path"));
    b.view.settings.samples_per_pixel = 3;
    b.view.sampler = make_sampler("sobol", 3);
    a.view.settings.threads = 1;
    a.view.settings.tile_size = 16;
    b.view.settings.threads = 2;
    b.view.settings.tile_size = 3;
    const Film fa = render_film(a);
    const Film fb = render_film(b);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            ASSERT_EQ(fa.pixel(x, y), fb.pixel(x, y)) << x << "," << y;
        }
    }
}

}  // namespace
}  // namespace glint
