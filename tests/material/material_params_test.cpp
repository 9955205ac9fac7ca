// Materials and textures as a scene file gives them: every type builds, and each bad value is an
// error at its own line.
#include <gtest/gtest.h>

#include "glint/params/diagnostics.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "material/bsdf_checks.hpp"

namespace glint {
namespace {

Scene build(const std::string& yaml) {
    return build_scene(parse_scene_text(yaml, "test.yaml", GLINT_SOURCE_DIR));
}

// The line of the error a scene raises, and its message.
std::pair<int, std::string> error_of(const std::string& yaml) {
    try {
        build(yaml);
    } catch (const SceneError& e) {
        return {e.position().line, e.message()};
    }
    return {0, "no error"};
}

TEST(MaterialParams, EveryMaterialAndTextureBuilds) {
    const Scene scene = build(R"(
materials:
  a: {type: matte, albedo: {type: checker, scale: 4, even: 0.9, odd: [0.1, 0.2, 0.3], space: solid}}
  b: {type: phong, diffuse: 0.5, specular: 0.3, exponent: 50}
  c: {type: plastic, diffuse: {type: noise, scale: 2, octaves: 4, color_a: 0.1, color_b: 0.7}, ior: 1.4}
  d: {type: mirror, reflectance: 0.9}
  e: {type: metal, albedo: [0.9, 0.6, 0.2], fuzz: 0.2}
  f: {type: glossy, reflectance: {type: constant, value: 0.5}, roughness: 0.5}
  g: {type: dielectric, ior: 2.417, absorption: [0.1, 0.2, 0.3]}
  h: {type: emissive, radiance: [1, 0.9, 0.8], scale: 4, two_sided: true}
)");
    ASSERT_EQ(scene.world->materials.size(), 8u);
    const Hit hit = testing::test_hit();
    EXPECT_EQ(scene.world->materials[6]->absorption(), Rgb(0.1, 0.2, 0.3));
    EXPECT_EQ(scene.world->materials[7]->emitted(hit, -hit.normal), Rgb(4, 3.6, 3.2));  // two-sided
    // The checker albedo reaches the matte surface: ambient reflectance is the texture's value.
    const Rgb albedo = scene.world->materials[0]->bsdf(hit).ambient_reflectance();
    EXPECT_TRUE(albedo == Rgb(0.9) || albedo == Rgb(0.1, 0.2, 0.3));
}

TEST(MaterialParams, EmissiveIsOneSidedByDefault) {
    const Scene scene = build("materials: {lamp: {type: emissive, radiance: 2}}\n");
    const Hit hit = testing::test_hit();
    EXPECT_EQ(scene.world->materials[0]->emitted(hit, hit.normal), Rgb(2.0));
    EXPECT_EQ(scene.world->materials[0]->emitted(hit, -hit.normal), Rgb());
}

TEST(MaterialParams, BadValuesAreErrorsAtTheirLine) {
    auto [line, message] = error_of("materials:\n  p: {type: phong, diffuse: 0.7,\n      specular: 0.5}\n");
    EXPECT_EQ(line, 3) << message;
    EXPECT_NE(message.find("must not exceed 1"), std::string::npos) << message;

    std::tie(line, message) =
        error_of("materials:\n  m:\n    type: metal\n    roughness: 0.1\n    fuzz: 0.2\n");
    EXPECT_EQ(line, 5) << message;

    std::tie(line, message) =
        error_of("materials:\n  m:\n    type: matte\n    albedo: {type: checker, odd: 1.5}\n");
    EXPECT_EQ(line, 4) << message;
    EXPECT_NE(message.find("[0, 1]"), std::string::npos) << message;

    std::tie(line, message) = error_of("materials:\n  m:\n    type: matte\n    albedo: {type: chekcer}\n");
    EXPECT_EQ(line, 4) << message;
    EXPECT_NE(message.find("did you mean 'checker'"), std::string::npos) << message;

    std::tie(line, message) = error_of(
        "materials:\n  m:\n    type: matte\n    albedo:\n      type: image\n      file: missing.png\n");
    EXPECT_EQ(line, 6) << message;
    EXPECT_NE(message.find("missing.png"), std::string::npos) << message;

    std::tie(line, message) = error_of("materials:\n  g: {type: dielectric,\n    absorption: [0, -1, 0]}\n");
    EXPECT_EQ(line, 3) << message;

    std::tie(line, message) = error_of("materials:\n  g:\n    type: dielectric\n    ior: 0\n");
    EXPECT_EQ(line, 4) << message;

    std::tie(line, message) = error_of("materials:\n  e:\n    type: emissive\n    radiance: -1\n");
    EXPECT_EQ(line, 4) << message;

    std::tie(line, message) =
        error_of("materials:\n  t:\n    type: matte\n    albedo: {type: noise, octaves: 40}\n");
    EXPECT_EQ(line, 4) << message;
}

TEST(MaterialParams, PrincipledTakesNumbersAndTexturesForEveryKey) {
    const Scene scene = build(R"(
materials:
  plain: {type: principled}
  gold: {type: principled, base_color: [1.0, 0.78, 0.34], metallic: 1, roughness: 0.2}
  tiled:
    type: principled
    base_color: {type: checker, scale: 4, even: 0.9, odd: [0.1, 0.2, 0.3]}
    metallic: {type: checker, scale: 4, even: 0, odd: 1}
    roughness: {type: noise, scale: 2, color_a: 0.2, color_b: 0.8}
    ior: 1.45
    specular: 0.5
)");
    ASSERT_EQ(scene.world->materials.size(), 3u);
    const Hit hit = testing::test_hit();
    // The defaults: a base of 0.8 under a layer of F₀ = 0.04.
    EXPECT_NEAR(scene.world->materials[0]->bsdf(hit).ambient_reflectance().g, 0.04 + 0.96 * 0.96 * 0.8,
                1e-12);
    EXPECT_NEAR(scene.world->materials[1]->bsdf(hit).ambient_reflectance().b, 0.34, 1e-12);
}

TEST(MaterialParams, PrincipledBadValuesAreErrorsAtTheirLine) {
    auto [line, message] = error_of("materials:\n  p:\n    type: principled\n    rougness: 0.3\n");
    EXPECT_EQ(line, 4) << message;
    EXPECT_NE(message.find("did you mean 'roughness'"), std::string::npos) << message;

    std::tie(line, message) = error_of("materials:\n  p:\n    type: principled\n    metallic: 1.5\n");
    EXPECT_EQ(line, 4) << message;
    EXPECT_NE(message.find("[0, 1]"), std::string::npos) << message;

    std::tie(line, message) = error_of("materials:\n  p:\n    type: principled\n    metallic: -0.1\n");
    EXPECT_EQ(line, 4) << message;

    std::tie(line, message) =
        error_of("materials:\n  p:\n    type: principled\n    roughness: {type: checker, odd: 2}\n");
    EXPECT_EQ(line, 4) << message;
    EXPECT_NE(message.find("[0, 1]"), std::string::npos) << message;

    std::tie(line, message) =
        error_of("materials:\n  p:\n    type: principled\n    base_color: [1, 1.2, 1]\n");
    EXPECT_EQ(line, 4) << message;

    std::tie(line, message) = error_of("materials:\n  p:\n    type: principled\n    ior: 0.8\n");
    EXPECT_EQ(line, 4) << message;

    std::tie(line, message) = error_of("materials:\n  p:\n    type: principled\n    specular: 2\n");
    EXPECT_EQ(line, 4) << message;
}

}  // namespace
}  // namespace glint
