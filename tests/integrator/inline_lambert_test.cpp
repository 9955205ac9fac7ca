// The path tracer shades a Matte of constant albedo through LambertBsdf, inline, and any other material
// through its Bsdf's virtual lobes (PathIntegrator::scatter). The two must give the same image to the
// bit: here the same albedo reaches the renderer once as a constant (the inline lobe) and once as a
// texture that is not a ConstantTexture (the virtual one), inside a closed sphere with an area light
// (next-event estimation, its MIS weights, Russian roulette) and a point light.
#include <gtest/gtest.h>

#include <memory>
#include <utility>

#include "glint/material/matte.hpp"
#include "glint/texture/checker.hpp"
#include "integrator/radiance_util.hpp"

namespace glint {
namespace {

// A constant colour through a texture that is not a ConstantTexture: a checker of two equal squares.
std::shared_ptr<const Texture> uniform_checker(const Rgb& value) {
    const auto square = std::make_shared<ConstantTexture>(value);
    return std::make_shared<CheckerTexture>(square, square, 1.0, CheckerTexture::Space::Solid);
}

Film render_inside_sphere(std::unique_ptr<Material> material) {
    Scene scene = test::scene_from_yaml(
        "render: {width: 16, height: 12, samples: 8, integrator: path, max_depth: 12}\n"
        "camera: {eye: [0, 0, 0], look_at: [0, 0, -1], fov: 70}\n"
        "objects: [{type: sphere, radius: 5}]\n"
        "lights: [{type: point, position: [1, -2, 1], intensity: 4},\n"
        "         {type: area, radiance: 6,\n"
        "          shape: {type: rectangle, corner: [-1, 4, -2], edge1: [2, 0, 0], edge2: [0, 0, 2]}}]\n");
    // A freshly built world that nothing else shares: the test may change it.
    World& world = const_cast<World&>(*scene.world);
    world.materials[world.shape_materials[0]] = std::move(material);
    return test::render_film(scene);
}

TEST(InlineLambert, ThePathTracersImageIsTheBitsOfTheVirtualLobes) {
    const Rgb albedo(0.7, 0.45, 0.2);
    auto inline_lobe = std::make_unique<Matte>(albedo);
    ASSERT_NE(inline_lobe->constant_lambert(), nullptr);
    auto virtual_lobe = std::make_unique<Matte>(uniform_checker(albedo));
    ASSERT_EQ(virtual_lobe->constant_lambert(), nullptr);

    const Film a = render_inside_sphere(std::move(inline_lobe));
    const Film b = render_inside_sphere(std::move(virtual_lobe));
    double sum = 0;
    for (int y = 0; y < 12; ++y) {
        for (int x = 0; x < 16; ++x) {
            const Rgb p = a.pixel(x, y);
            const Rgb q = b.pixel(x, y);
            EXPECT_EQ(p.r, q.r) << x << ", " << y;
            EXPECT_EQ(p.g, q.g) << x << ", " << y;
            EXPECT_EQ(p.b, q.b) << x << ", " << y;
            sum += p.r + p.g + p.b;
        }
    }
    EXPECT_GT(sum, 0);  // lit: the comparison compares something
}

}  // namespace
}  // namespace glint
