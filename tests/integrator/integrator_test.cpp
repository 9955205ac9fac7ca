// Integrators against radiance known without the code: furnaces, Lambert's law, a mirror, the penumbra
// of an area light, and the agreement of the integrators where their physics coincide.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include "glint/core/hash.hpp"
#include "glint/image/image_io.hpp"
#include "glint/integrator/direct_lighting.hpp"
#include "glint/integrator/path.hpp"
#include "glint/light/area.hpp"
#include "glint/scene/scene_set.hpp"
#include "integrator/radiance_util.hpp"
#include "integrator/test_materials.hpp"

namespace glint {
namespace {

using test::region_mean;
using test::render_film;
using test::scene_from_yaml;

// Gives shape `index` the material `material`; when it emits, it becomes an area light.
void set_material(Scene& scene, size_t index, std::unique_ptr<Material> material) {
    // A freshly built world that nothing else shares: the test may change it.
    World& world = const_cast<World&>(*scene.world);
    world.materials.push_back(std::move(material));
    ASSERT_TRUE(attach_material(world, index, static_cast<std::uint32_t>(world.materials.size() - 1)));
}

// |mean − expected| within four standard errors (plus rounding).
void expect_mean(const test::RegionMean& m, double expected) {
    EXPECT_NEAR(m.mean, expected, 4 * m.standard_error + 1e-9 * std::abs(expected))
        << "standard error " << m.standard_error;
}

// The per-pixel difference of two renders of the same scene, averaged over the image: zero within four
// standard errors when both estimate the same radiance (the spatial variation of the image cancels).
void expect_same_radiance(const Film& a, const Film& b) {
    Film difference(a.width(), a.height());
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            difference.add_sample(x, y, a.pixel(x, y) - b.pixel(x, y));
        }
    }
    const test::RegionMean d = region_mean(difference, 0, 0, a.width(), a.height());
    const test::RegionMean mean_a = region_mean(a, 0, 0, a.width(), a.height());
    EXPECT_GT(mean_a.mean, 0.01);  // something is lit
    EXPECT_NEAR(d.mean, 0, 4 * d.standard_error + 1e-9)
        << "mean " << mean_a.mean << ", standard error " << d.standard_error;
    EXPECT_LT(d.standard_error, 0.05 * mean_a.mean);  // and the comparison has power
}

// The path tracer as built and with light sampling off (smallpt's estimator: each bounce's emission
// found by the BSDF sample alone, counted in full).
constexpr const char* kPathEstimators[] = {"path", "{type: path, sample_lights: false}"};

TEST(Furnace, ConvexMatteUnderUniformSkyReflectsAlbedoTimesRadiance) {
    for (const double albedo : {0.5, 1.0}) {
        const Scene scene = scene_from_yaml(R"(
render: {width: 16, height: 16, samples: 16, integrator: path, max_depth: 50}
camera: {eye: [0, 0, 4], look_at: [0, 0, 0], fov: 30}
objects: [{type: sphere, radius: 1, material: {type: matte, albedo: )" +
                                            std::to_string(albedo) + R"(}}]
lights: [{type: environment, radiance: 1.5}]
)");
        const Film film = render_film(scene);
        expect_mean(region_mean(film, 4, 4, 12, 12), albedo * 1.5);
        EXPECT_NEAR(film.pixel(0, 0).g, 1.5, 1e-12);  // the sky itself, in a corner
    }
}

TEST(Furnace, ConvexMatteUnderAConstantImageEnvironment) {
    // The image path (loading, importance sampling with its sin θ Jacobian) must integrate to the same.
    const auto file =
        std::filesystem::temp_directory_path() / ("glint-furnace-" + std::to_string(::getpid()) + ".pfm");
    Image sky(16, 8);
    for (float& v : sky.rgb) {
        v = 0.7f;
    }
    write_image(sky, file);
    // Sampled by light samples and MIS, or found by the BSDF's samples alone.
    for (const char* integrator : kPathEstimators) {
        const Scene scene = scene_from_yaml(std::string(R"(
render: {width: 16, height: 16, samples: 16, max_depth: 50, integrator: )") +
                                            integrator + R"(}
camera: {eye: [0, 0, 4], look_at: [0, 0, 0], fov: 30}
objects: [{type: sphere, radius: 1, material: {type: matte, albedo: 0.5}}]
lights: [{type: environment, image: ')" + file.string() +
                                            R"(', rotation: 40}]
)");
        const Film film = render_film(scene);
        expect_mean(region_mean(film, 4, 4, 12, 12), 0.5 * 0.7f);
    }
    std::filesystem::remove(file);
}

TEST(Furnace, MatteFloorUnderAGradientSkyWithoutShadowRays) {
    // A sky linear in the direction, L(ω) = a + b ω_y (the gradient: a = (bottom + top)/2,
    // b = (top − bottom)/2), seen by an upward Lambertian floor reflects ρ (a + 2b/3): ∫ ω_y cos θ dω over
    // the upper hemisphere is 2π/3. The path tracer leaves such a sky to BSDF sampling, so it traces no
    // shadow ray at all and must still converge to that.
    const Scene scene = scene_from_yaml(R"(
render: {width: 16, height: 16, samples: 64, integrator: path, max_depth: 50}
camera: {eye: [0, 10, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 20}
objects: [{type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, albedo: 0.5}}]
lights: [{type: environment, radiance: {type: gradient, bottom: [1, 1, 1], top: [0.2, 0.4, 1]}}]
)");
    Film film(16, 16);
    const RenderStats stats = render(scene, film);
    EXPECT_EQ(stats.rays.shadow, 0u);
    EXPECT_GT(stats.rays.secondary, 0u);
    const double bottom[3] = {1, 1, 1};
    const double top[3] = {0.2, 0.4, 1};
    for (int channel = 0; channel < 3; ++channel) {
        const double a = (bottom[channel] + top[channel]) / 2;
        const double b = (top[channel] - bottom[channel]) / 2;
        expect_mean(region_mean(film, 0, 0, 16, 16, channel), 0.5 * (a + 2 * b / 3));
    }
}

TEST(Furnace, GlassUnderAUniformSkyNeitherGainsNorLosesLight) {
    // A clear dielectric sphere under a uniform sky: every path through it ends in the sky, so each
    // pixel sees the sky's radiance; Whitted's Fresnel split must give it too, up to the branches it
    // prunes.
    for (const char* integrator : {"whitted", "path"}) {
        Scene scene = scene_from_yaml(std::string(R"(
render: {width: 12, height: 12, samples: 4, max_depth: 40, integrator: )") +
                                      integrator + R"(}
camera: {eye: [0, 0, 4], look_at: [0, 0, 0], fov: 30}
objects: [{type: sphere, radius: 1}]
lights: [{type: environment, radiance: 1}]
)");
        set_material(scene, 0, std::make_unique<test::SmoothGlass>(1.5, Rgb{}));
        const Film film = render_film(scene);
        if (std::string(integrator) == "path") {  // Russian roulette: exact only in the mean
            expect_mean(region_mean(film, 0, 0, 12, 12), 1.0);
            continue;
        }
        for (int y = 0; y < 12; ++y) {
            for (int x = 0; x < 12; ++x) {
                EXPECT_NEAR(film.pixel(x, y).r, 1.0, 2e-3) << integrator << " " << x << ", " << y;
                EXPECT_LE(film.pixel(x, y).r, 1.0 + 1e-9) << integrator << " " << x << ", " << y;
            }
        }
    }
}

TEST(Furnace, TheLibraryDielectricSplitsWithoutGainOrLoss) {
    // The same with the material library's dielectric (exact Fresnel, η² radiance scaling across the
    // interface, which cancels on the way out): Whitted finds both of its lobes at the two ends of u.
    const Scene scene = scene_from_yaml(R"(
render: {width: 12, height: 12, samples: 1, max_depth: 40, integrator: whitted}
camera: {eye: [0, 0, 4], look_at: [0, 0, 0], fov: 30}
objects: [{type: sphere, radius: 1, material: {type: dielectric, ior: 1.5}}]
lights: [{type: environment, radiance: 1}]
)");
    Film film(12, 12);
    const RenderStats stats = render(scene, film);
    for (int y = 0; y < 12; ++y) {
        for (int x = 0; x < 12; ++x) {
            EXPECT_NEAR(film.pixel(x, y).g, 1.0, 2e-3) << x << ", " << y;
        }
    }
    // Split, not chosen: each camera ray that meets the glass spawns a reflected and a refracted ray,
    // and the refracted one two more where it leaves.
    EXPECT_GT(stats.rays.secondary, 3 * stats.rays.camera / 2);
}

TEST(AmbientOcclusion, ProbesSeeWhatBlocksTheAmbientLight) {
    const auto floor_radiance = [](const std::string& extra_objects, const std::string& ao) {
        const Scene scene = scene_from_yaml(R"(
render: {width: 8, height: 8, samples: 16, integrator: raycast}
camera: {eye: [2, 0.5, 0], look_at: [2, 0, 0], up: [0, 0, -1], fov: 20}
objects:
  - {type: plane, normal: [0, 1, 0], material: {type: matte, albedo: 0.5}}
)" + extra_objects + "lights: [" + ao + "]\n");
        return region_mean(render_film(scene), 0, 0, 8, 8);
    };
    // Open sky: ρ L. A ceiling at height 1: out of reach of probes 0.5 long.
    EXPECT_NEAR(floor_radiance("", "{type: ambient-occlusion, radiance: 1}").mean, 0.5, 1e-12);
    const std::string ceiling = "  - {type: plane, point: [0, 1, 0], normal: [0, 1, 0]}\n";
    EXPECT_NEAR(floor_radiance(ceiling, "{type: ambient-occlusion, radiance: 1, distance: 0.5}").mean, 0.5,
                1e-12);
    // Probes 2 long reach the ceiling when cos θ > 1/2; for cosine-weighted directions cos² θ is uniform,
    // so a quarter of them get past: ρ L / 4.
    expect_mean(floor_radiance(ceiling, "{type: ambient-occlusion, radiance: 1, distance: 2}"), 0.125);
    // A wall x = 0 beside the floor blocks the half of the cosine-weighted hemisphere towards it.
    expect_mean(floor_radiance("  - {type: plane, normal: [1, 0, 0]}\n",
                               "{type: ambient-occlusion, radiance: 1, samples: 4}"),
                0.25);
}

TEST(Furnace, InsideAClosedEmittingSphereRadianceIsEmissionOverOneMinusAlbedo) {
    for (const char* integrator : kPathEstimators) {
        for (const double albedo : {0.5, 0.8}) {
            Scene scene = scene_from_yaml(std::string(R"(
render: {width: 8, height: 8, samples: 16, max_depth: 1000, integrator: )") +
                                          integrator + R"(}
camera: {eye: [0, 0, 0], look_at: [0, 0, -1], fov: 90}
objects: [{type: sphere, center: [0.1, 0.2, 0], radius: 1}]
)");
            set_material(scene, 0, std::make_unique<test::EmittingMatte>(Rgb(albedo), Rgb(1.0)));
            const Film film = render_film(scene);
            expect_mean(region_mean(film, 0, 0, 8, 8), 1 / (1 - albedo));  // Lₑ Σ ρᵏ
        }
    }
}

TEST(Lambert, MatteUnderASphereLightReflectsAlbedoTimesRadianceTimesSineSquared) {
    // A sphere light of radius R and radiance L whose centre is at height H on the normal of a
    // Lambertian floor gives it the irradiance π L sin²α, sin α = R/H, so the floor reflects
    // ρ L (R/H)² = 0.5 × 2 × (1/4)² = 0.0625. At a distance x from the foot of the normal it is
    // π L R² H / (H² + x²)^(3/2), 1.5 x²/H² less; the camera sees a patch 0.013 long centred on the
    // foot, where that is under 10⁻⁵ (light sampling's standard error here is about 10⁻⁵ of the value).
    for (const char* integrator : kPathEstimators) {
        const Scene scene = scene_from_yaml(std::string(R"(
render: {width: 8, height: 8, samples: 1024, max_depth: 50, integrator: )") +
                                            integrator + R"(}
camera: {eye: [3, 1.5, 0], look_at: [0, 0, 0], fov: 0.1}
objects: [{type: plane, normal: [0, 1, 0], material: {type: matte, albedo: 0.5}}]
lights: [{type: area, shape: {type: sphere, center: [0, 4, 0], radius: 1}, radiance: 2}]
)");
        Film film(8, 8);
        const RenderStats stats = render(scene, film);
        expect_mean(region_mean(film, 0, 0, 8, 8), 0.0625);
        const bool samples_lights = std::string(integrator) == "path";
        EXPECT_EQ(stats.rays.shadow > 0, samples_lights) << integrator;
    }
}

TEST(Lambert, MatteUnderDirectionalLightIsAlbedoOverPiTimesIrradianceCosine) {
    for (const char* integrator : {"raycast", "whitted", "path"}) {
        const Scene scene = scene_from_yaml(std::string(R"(
render: {width: 8, height: 8, samples: 4, max_depth: 1, integrator: )") +
                                            integrator + R"(}
camera: {eye: [0, 5, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 30}
objects: [{type: plane, normal: [0, 1, 0], material: {type: matte, albedo: 0.6}}]
lights: [{type: directional, direction: [0, -1, -1.7320508075688772], irradiance: 2}]
)");
        const Film film = render_film(scene);
        const double expected = 0.6 / kPi * 2 * 0.5;  // cos θ = cos 60°
        for (int y = 0; y < 8; ++y) {
            for (int x = 0; x < 8; ++x) {
                EXPECT_NEAR(film.pixel(x, y).r, expected, 1e-12 * expected) << integrator;
            }
        }
    }
}

TEST(Mirror, ReflectsAnEmitterAtTheMirroredPixel) {
    for (const char* integrator : {"whitted", "path"}) {
        Scene scene = scene_from_yaml(std::string(R"(
render: {width: 48, height: 48, samples: 4, max_depth: 3, integrator: )") +
                                      integrator + R"(}
camera: {eye: [0, 1, 10], look_at: [0, 1, 0], fov: 40}
objects: [{type: plane, normal: [0, 1, 0]}]
lights: [{type: area, shape: {type: sphere, center: [0, 2, 0], radius: 0.5}, radiance: 3}]
)");
        set_material(scene, 0, std::make_unique<test::PerfectMirror>());
        const Film film = render_film(scene);
        // Pixel rows of a point at height y on the plane z = 0: 24 − 24 (y − 1) / (10 tan 20°); the
        // mirror image of the sphere's centre (0, 2, 0) is (0, −2, 0), 0.44 units farther.
        const double t = std::tan(radians(20));
        const int direct_row = static_cast<int>(24 - 24 * (1.0 / 10) / t);
        const int mirrored_row = static_cast<int>(24 + 24 * (3.0 / 10) / t);
        EXPECT_NEAR(film.pixel(23, direct_row).r, 3, 1e-12) << integrator;
        EXPECT_NEAR(film.pixel(24, mirrored_row).r, 3, 1e-12) << integrator;
        EXPECT_EQ(film.pixel(23, (direct_row + mirrored_row) / 2).r, 0)
            << integrator;  // black sky in between
        ASSERT_LT(mirrored_row, 48);
        EXPECT_EQ(film.pixel(23, mirrored_row - 6).r, 0) << integrator;  // beside the reflection
    }
}

// The floor point (x, 0, 0) under a spherical light of radius R at height H, shadowed by a sphere of
// radius r at height h, both on the y axis: the fraction of the light's samples that reach it.
double visible_fraction(const Scene& scene, double x, int n) {
    Hit at;
    at.point = {x, 0, 0};
    at.normal = at.shading_normal = {0, 1, 0};
    RayCounters rays;
    int visible = 0;
    for (int i = 0; i < n; ++i) {
        const std::uint64_t h = hash_values(17, static_cast<std::uint64_t>(i));
        const Point2 u{(i + static_cast<double>(h >> 11) * 0x1p-53) / n,
                       static_cast<double>(hash_values(h) >> 11) * 0x1p-53};
        const auto s = scene.world->lights[0]->sample(at, u);
        EXPECT_TRUE(s);
        visible += s && !shadowed(*scene.world, at, *s, rays) ? 1 : 0;
    }
    return static_cast<double>(visible) / n;
}

TEST(Shadows, AreaLightPenumbraMatchesTheTangentLines) {
    const double H = 4, R = 0.6, h = 2, r = 0.4;
    const Scene scene = scene_from_yaml(R"(
objects:
  - {type: plane, normal: [0, 1, 0]}
  - {type: sphere, center: [0, 2, 0], radius: 0.4}
lights: [{type: area, shape: {type: sphere, center: [0, 4, 0], radius: 0.6}, radiance: 1}]
)");
    // In the plane through the axis, a line n·p = c tangent to both circles has
    // n_y (H − h) = s₁R − s₂r and c = n_y h − s₂ r. Same signs: the outer tangents bound the umbra;
    // opposite signs: the inner tangents bound the penumbra. Where they meet the floor: x = c / n_x.
    const auto floor_x = [&](double s1, double s2) {
        const double ny = (s1 * R - s2 * r) / (H - h);
        return (ny * h - s2 * r) / std::sqrt(1 - ny * ny);
    };
    const double umbra = std::max(floor_x(1, 1), floor_x(-1, -1));
    const double penumbra = std::max(floor_x(1, -1), floor_x(-1, 1));
    EXPECT_NEAR(umbra, 0.2, 0.01);  // similar triangles: the umbra cone's apex lies 4 below the blocker
    const double margin = 0.02 * (penumbra - umbra);
    EXPECT_EQ(visible_fraction(scene, 0, 256), 0);
    EXPECT_EQ(visible_fraction(scene, umbra - margin, 256), 0);
    const double middle = visible_fraction(scene, 0.5 * (umbra + penumbra), 256);
    EXPECT_GT(middle, 0.1);
    EXPECT_LT(middle, 0.9);
    EXPECT_EQ(visible_fraction(scene, penumbra + margin, 256), 1);
    // Just inside either edge, some rays pass and some do not.
    EXPECT_GT(visible_fraction(scene, umbra + 4 * margin, 4096), 0);
    EXPECT_LT(visible_fraction(scene, penumbra - 4 * margin, 4096), 1);
}

constexpr const char* kMatteScene = R"(
camera: {eye: [0, 2, 7], look_at: [0, 0.7, 0], fov: 40}
objects:
  - {type: plane, normal: [0, 1, 0], material: {type: matte, albedo: 0.7}}
  - {type: sphere, center: [0, 1, 0], radius: 1, material: {type: matte, albedo: [0.6, 0.4, 0.2]}}
  - {type: sphere, center: [-2, 0.5, 1], radius: 0.5, material: {type: matte, albedo: 0.9}}
lights:
  - {type: point, position: [3, 5, 3], intensity: 5}
  - {type: area, shape: {type: sphere, center: [-1, 4.5, 1], radius: 2.2}, radiance: 1}
)";

TEST(IntegratorsAgree, RaycastAndDirectOnlyPathTracingOnMatteScenes) {
    RenderFlags overrides;
    overrides.width = 24;
    overrides.height = 16;
    overrides.samples_per_pixel = 64;
    overrides.max_depth = 1;
    overrides.integrator = "raycast";
    const Film raycast = render_film(scene_from_yaml(kMatteScene, overrides));
    overrides.integrator = "path";
    overrides.seed = 2;
    const Film path = render_film(scene_from_yaml(kMatteScene, overrides));
    expect_same_radiance(raycast, path);
}

// A matte floor lit by a point light, seen directly and in a mirror: Whitted's recursion and the path
// tracer's specular bounces compute the same light, sample for sample.
TEST(IntegratorsAgree, WhittedAndPathSeeAPointLitFloorInAMirror) {
    const std::string yaml = R"(
render: {width: 24, height: 16, samples: 4, max_depth: 2}
camera: {eye: [0, 2, 6], look_at: [0, 1, 0], fov: 50}
objects:
  - {type: plane, normal: [0, 1, 0], material: {type: matte, albedo: 0.7}}
  - {type: plane, point: [0, 0, -2], normal: [0, -0.2, 1]}
lights: [{type: point, position: [-1, 4, 3], intensity: 20}]
)";
    RenderFlags overrides;
    overrides.integrator = "whitted";
    Scene whitted = scene_from_yaml(yaml, overrides);
    set_material(whitted, 1, std::make_unique<test::PerfectMirror>());
    overrides.integrator = "path";
    Scene path = scene_from_yaml(yaml, overrides);
    set_material(path, 1, std::make_unique<test::PerfectMirror>());
    const Film a = render_film(whitted);
    const Film b = render_film(path);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 24; ++x) {
            EXPECT_NEAR(a.pixel(x, y).g, b.pixel(x, y).g, 1e-9) << x << ", " << y;
        }
    }
    EXPECT_GT(region_mean(a, 0, 0, 24, 4).mean, 0.01);  // the top rows see the floor in the mirror
}

// A matte that takes direct light only (its BSDF sampling ends the path): with it the path tracer's
// light transport is Whitted's, so the two must agree in expectation.
class DirectOnlyMatte final : public Material {
  public:
    explicit DirectOnlyMatte(double albedo) : albedo_(albedo) {}

  protected:
    Rgb evaluate(const MaterialPoint&, const Vec3& wo, const Vec3& wi) const override {
        return wo.z * wi.z > 0 ? Rgb(albedo_ * kInvPi) : Rgb{};
    }
    std::optional<BsdfSample> sample(const MaterialPoint&, const Vec3&, Point2) const override {
        return std::nullopt;
    }
    double pdf(const MaterialPoint&, const Vec3&, const Vec3&) const override { return 0; }

  private:
    double albedo_;
};

TEST(IntegratorsAgree, WhittedAndPathSeeAPointLitFloorThroughAnAbsorbingGlassSlab) {
    const std::string yaml = R"(
render: {width: 24, height: 16, samples: 16, max_depth: 6}
camera: {eye: [0, 2, 6], look_at: [0, 0.8, 0], fov: 40}
objects:
  - {type: plane, normal: [0, 1, 0]}
  # An upright slab between the camera and the lit floor, 0.4 thick, filling the lower half of the view.
  - {type: box, min: [-4, 0.01, 3], max: [4, 1.5, 3.4]}
lights: [{type: point, position: [-2, 5, 1], intensity: 30}]
)";
    const auto make = [&](const char* integrator, std::uint64_t seed) {
        RenderFlags overrides;
        overrides.integrator = integrator;
        overrides.seed = seed;
        Scene scene = scene_from_yaml(yaml, overrides);
        set_material(scene, 0, std::make_unique<DirectOnlyMatte>(0.8));
        set_material(scene, 1, std::make_unique<test::SmoothGlass>(1.5, Rgb(0.1, 0.3, 0.6)));
        return scene;
    };
    const Film whitted = render_film(make("whitted", 1));
    const Film path = render_film(make("path", 2));
    expect_same_radiance(whitted, path);
}

TEST(Beer, TransmittanceFallsOffExponentially) {
    Scene scene = scene_from_yaml(R"(
render: {width: 1, height: 1, samples: 1, integrator: whitted, max_depth: 4}
camera: {eye: [0, 0, 5], look_at: [0, 0, 0], fov: 0.01}
objects: [{type: sphere, radius: 1}]
lights: [{type: environment, radiance: 1}]
)");
    // An index-matched glass (η = 1: no reflection, no bending) of σ_a = 0.5 and diameter 2.
    set_material(scene, 0, std::make_unique<test::SmoothGlass>(1.0, Rgb(0.5, 0, 1)));
    const Film film = render_film(scene);
    EXPECT_NEAR(film.pixel(0, 0).r, std::exp(-1.0), 1e-6);
    EXPECT_NEAR(film.pixel(0, 0).g, 1.0, 1e-6);
    EXPECT_NEAR(film.pixel(0, 0).b, std::exp(-2.0), 1e-6);
}

// Next-event estimation's weight over the light's density is the power heuristic's weight divided by
// it, also where the other density is zero or far apart, and where the squares overflow (no weight
// then, as the power heuristic's NaN gives none).
TEST(Mis, PowerHeuristicOverPdfIsThePowerHeuristicOverThePdf) {
    for (const double a : {1e-100, 0.3, 1.0, 7.5, 1e100, 1e200}) {
        for (const double b : {0.0, 1e-110, 0.3, 2.0, 1e110, 1e200}) {
            const double expected = power_heuristic(a, b) / a;
            const double got = power_heuristic_over_pdf(a, b);
            if (std::isnan(expected)) {
                EXPECT_FALSE(got > 0) << a << ", " << b << ": the sample must not count";
            } else {
                EXPECT_NEAR(got, expected, 1e-15 * expected + 1e-300) << a << ", " << b;
            }
        }
    }
    EXPECT_EQ(power_heuristic_over_pdf(2.0, 0.0), 0.5);  // no other strategy: the estimator's 1/pdf
    EXPECT_EQ(power_heuristic_over_pdf(0.0, 0.0), 0.0);
}

}  // namespace
}  // namespace glint
