// Each integrator looks a material's textures up once per hit (Material::bsdf), however often it then
// evaluates, samples or asks the pdf of the BSDF there. Counted with a texture that counts its calls,
// inside a closed sphere, where the number of hits per camera sample is known.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>

#include "glint/material/fuzzy_metal.hpp"
#include "glint/material/matte.hpp"
#include "glint/material/metal.hpp"
#include "glint/material/mirror.hpp"
#include "glint/material/phong.hpp"
#include "glint/material/plastic.hpp"
#include "integrator/radiance_util.hpp"

namespace glint {
namespace {

// A constant colour that counts how often it is evaluated (from any render thread).
class CountingTexture final : public Texture {
  public:
    explicit CountingTexture(const Rgb& value) : value_(value) {}
    Rgb evaluate(const Hit&) const override {
        evaluations_.fetch_add(1, std::memory_order_relaxed);
        return value_;
    }
    double min_value() const override { return std::min({value_.r, value_.g, value_.b}); }
    double max_value() const override { return value_.max_component(); }
    std::uint64_t evaluations() const { return evaluations_.load(); }

  private:
    Rgb value_;
    mutable std::atomic<std::uint64_t> evaluations_{0};
};

constexpr int kWidth = 8, kHeight = 6, kSamples = 4;
constexpr std::uint64_t kCameraSamples = std::uint64_t{kWidth} * kHeight * kSamples;

// The camera inside a closed sphere lit by a point light and an ambient term: every ray hits the sphere,
// and none escapes.
Scene inside_sphere(const std::string& integrator, int max_depth, std::unique_ptr<Material> material) {
    RenderFlags flags;
    flags.integrator = integrator;
    flags.max_depth = max_depth;
    Scene scene = test::scene_from_yaml("render: {width: " + std::to_string(kWidth) +
                                            ", height: " + std::to_string(kHeight) +
                                            ", samples: " + std::to_string(kSamples) +
                                            "}\n"
                                            "camera: {eye: [0, 0, 0], look_at: [0, 0, -1], fov: 60}\n"
                                            "objects: [{type: sphere, radius: 5}]\n"
                                            "lights: [{type: point, position: [0, 2, 1], intensity: 10},\n"
                                            "         {type: ambient, radiance: 0.1}]\n",
                                        flags);
    // A freshly built world that nothing else shares: the test may change it.
    World& world = const_cast<World&>(*scene.world);
    world.materials[world.shape_materials[0]] = std::move(material);
    return scene;
}

TEST(TextureLookups, PathTracerReadsAMatteTextureOncePerScatteringHit) {
    // max_depth 3: a matte path scatters at exactly three hits (its cosine samples never fail and the
    // sphere is closed; roulette only decides after the third), and the fourth hit ends it unshaded.
    // Looking the texture up in evaluate (next-event estimation) and in sample would read it 6 times.
    const auto albedo = std::make_shared<CountingTexture>(Rgb(0.5));
    const Scene scene = inside_sphere("path", 3, std::make_unique<Matte>(albedo));
    const Film film = test::render_film(scene);
    EXPECT_GT(test::region_mean(film, 0, 0, kWidth, kHeight).mean, 0);
    EXPECT_EQ(albedo->evaluations(), 3 * kCameraSamples);
}

TEST(TextureLookups, DirectLightingIntegratorsReadAMatteTextureOncePerHit) {
    // One hit per camera sample: the ambient term, the light's f and (for Whitted) the probes for
    // delta lobes all use the one lookup.
    for (const std::string integrator : {"raycast", "whitted"}) {
        const auto albedo = std::make_shared<CountingTexture>(Rgb(0.5));
        const Scene scene = inside_sphere(integrator, 5, std::make_unique<Matte>(albedo));
        const Film film = test::render_film(scene);
        EXPECT_GT(test::region_mean(film, 0, 0, kWidth, kHeight).mean, 0) << integrator;
        EXPECT_EQ(albedo->evaluations(), kCameraSamples) << integrator;
    }
}

TEST(TextureLookups, EveryTexturedMaterialIsLookedUpOncePerHitInThePathTracer) {
    // max_depth 1: whatever the lobes do, each camera sample shades exactly one hit.
    struct Case {
        std::string name;
        int textures;  // how many counting textures the material reads
        std::function<std::unique_ptr<Material>(std::shared_ptr<const Texture>)> make;
    };
    const std::vector<Case> cases = {
        {"matte", 1, [](auto t) { return std::make_unique<Matte>(t); }},
        {"phong", 2, [](auto t) { return std::make_unique<Phong>(t, t, 20.0); }},
        {"plastic", 1, [](auto t) { return std::make_unique<Plastic>(t, 1.5); }},
        {"metal", 1, [](auto t) { return std::make_unique<Metal>(t, 0.3); }},
        {"mirror", 1, [](auto t) { return std::make_unique<Mirror>(t); }},
        {"fuzzy-metal", 1, [](auto t) { return std::make_unique<FuzzyMetal>(t, 0.5); }},
    };
    for (const Case& c : cases) {
        const auto texture = std::make_shared<CountingTexture>(Rgb(0.4));
        const Scene scene = inside_sphere("path", 1, c.make(texture));
        test::render_film(scene);
        EXPECT_EQ(texture->evaluations(), static_cast<std::uint64_t>(c.textures) * kCameraSamples) << c.name;
    }
}

}  // namespace
}  // namespace glint
