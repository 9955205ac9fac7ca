// AOVs (render/aov.hpp) on scenes where each value is known without the code: a plane of known colour
// seen square-on by an orthographic camera at a known distance, the same seen through a mirror, the
// sky, and the film's sample counts and variances against their formulas.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "glint/render/aov.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

const ImageLayer& layer(const std::vector<ImageLayer>& layers, const std::string& name) {
    for (const ImageLayer& l : layers) {
        if (l.name == name) {
            return l;
        }
    }
    throw std::runtime_error("no layer " + name);
}

std::vector<ImageLayer> aovs_of(const std::string& yaml, const std::string& list) {
    const Scene scene = test::scene_from_text(yaml);
    Film film(scene.view.settings.width, scene.view.settings.height);
    const RenderStats stats = render(*scene.world, scene.view, film);
    return render_aovs(*scene.world, scene.view, film, {0, 0, film.width(), film.height()},
                       stats.samples_per_pixel, parse_aov_list(list));
}

TEST(Aov, APlaneSeenSquareOnGivesItsColourItsNormalAndItsDistance) {
    // The camera looks down −z from z = 5 at the plane z = 0 (normal +z): depth 5 along every ray.
    const auto layers = aovs_of(
        "render: {width: 6, height: 4, samples: 8}\n"
        "camera: {type: orthographic, eye: [0, 0, 5], look_at: [0, 0, 0], height: 2}\n"
        "objects:\n  - {type: plane, point: [0, 0, 0], normal: [0, 0, 1], material: {type: matte, albedo: "
        "[0.25, "
        "0.5, 0.75]}}\n"
        "lights:\n  - {type: point, position: [0, 0, 3], intensity: 5}\n",
        "albedo,normal,depth,spp");
    ASSERT_EQ(layers.size(), 4u);
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 6; ++x) {
            const float* a = layer(layers, "albedo").pixel(x, y);
            EXPECT_FLOAT_EQ(a[0], 0.25f);
            EXPECT_FLOAT_EQ(a[1], 0.5f);
            EXPECT_FLOAT_EQ(a[2], 0.75f);
            const float* n = layer(layers, "normal").pixel(x, y);
            EXPECT_FLOAT_EQ(n[0], 0.0f);
            EXPECT_FLOAT_EQ(n[1], 0.0f);
            EXPECT_FLOAT_EQ(n[2], 1.0f);
            EXPECT_NEAR(layer(layers, "depth").pixel(x, y)[0], 5.0f, 1e-5);
            EXPECT_EQ(layer(layers, "spp").pixel(x, y)[0], 8.0f);
        }
    }
}

TEST(Aov, AMirrorIsLookedThroughForAlbedoAndNormalButNotForDepth) {
    // A mirror tilted 45° at z = 0 sends the camera's −z rays to −x, onto a red wall x = −3 (normal +x).
    const auto layers = aovs_of(
        "render: {width: 4, height: 4, samples: 4}\n"
        "camera: {type: orthographic, eye: [0, 0, 5], look_at: [0, 0, 0], height: 0.5}\n"
        "objects:\n"
        "  - {type: plane, point: [0, 0, 0], normal: [-1, 0, 1], material: {type: mirror, reflectance: "
        "0.9}}\n"
        "  - {type: plane, point: [-3, 0, 0], normal: [1, 0, 0], material: {type: matte, albedo: [0.8, 0.1, "
        "0.1]}}\n",
        "albedo,normal,depth");
    for (int y = 0; y < 4; ++y) {
        for (int x = 0; x < 4; ++x) {
            const float* a = layer(layers, "albedo").pixel(x, y);
            EXPECT_FLOAT_EQ(a[0], 0.8f);
            EXPECT_FLOAT_EQ(a[1], 0.1f);
            const float* n = layer(layers, "normal").pixel(x, y);
            EXPECT_NEAR(n[0], 1.0f, 1e-6);
            EXPECT_NEAR(n[2], 0.0f, 1e-6);
        }
    }
    // Depth is the mirror's: 5 at the centre column x = 0, 5 + x' where the tilted plane is z = x.
    const float centre = layer(layers, "depth").pixel(2, 2)[0];
    EXPECT_GT(centre, 4.8f);
    EXPECT_LT(centre, 5.2f);
}

TEST(Aov, TheSkyHasNoAlbedoNoNormalAndInfiniteDepth) {
    const auto layers = aovs_of(
        "render: {width: 3, height: 3, samples: 2}\nbackground: [0.5, 0.7, 1]\n"
        "camera: {eye: [0, 0, 5], look_at: [0, 0, 0], fov: 30}\nobjects: []\n",
        "albedo,normal,depth");
    EXPECT_EQ(layer(layers, "albedo").pixel(1, 1)[0], 0.0f);
    EXPECT_EQ(layer(layers, "normal").pixel(1, 1)[2], 0.0f);
    EXPECT_EQ(layer(layers, "depth").pixel(1, 1)[0], std::numeric_limits<float>::infinity());
}

TEST(Aov, VarianceIsTheSampleVarianceOfTheMeanLuminance) {
    Film film(2, 1);
    for (double v : {1.0, 2.0, 3.0, 4.0}) {
        film.add_sample(0, 0, Rgb(v));  // grey: luminance v
    }
    film.add_sample(1, 0, Rgb(3.0));
    // Unbiased variance of {1, 2, 3, 4} is 5/3; of their mean, 5/12. One sample: no estimate, 0.
    EXPECT_NEAR(film.mean_variance(0, 0), 5.0 / 12.0, 1e-12);
    EXPECT_EQ(film.mean_variance(1, 0), 0.0);
    // A constant emitter filling the view: every sample equal, variance 0 (up to rounding).
    const auto layers = aovs_of(
        "render: {width: 2, height: 2, samples: 16}\ncamera: {eye: [0, 0, 5], look_at: [0, 0, 0], fov: 5}\n"
        "objects:\n  - {type: sphere, radius: 1, material: {type: emissive, radiance: [2, 2, 2]}}\n",
        "variance");
    EXPECT_NEAR(layer(layers, "variance").pixel(1, 1)[0], 0.0f, 1e-12);
}

TEST(Aov, TheListIsCheckedWithADidYouMean) {
    EXPECT_TRUE(parse_aov_list("albedo,normal").normal);
    EXPECT_FALSE(parse_aov_list("albedo,normal").depth);
    try {
        parse_aov_list("albdo");
        FAIL();
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("unknown AOV 'albdo'; did you mean 'albedo'?"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(parse_aov_list(""), std::invalid_argument);
}

}  // namespace
}  // namespace glint
