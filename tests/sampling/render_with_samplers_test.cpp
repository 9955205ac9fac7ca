// Every sampler name renders the built-in scene through the library, and all agree on the image.
#include <gtest/gtest.h>

#include <cmath>

#include "glint/image/film.hpp"
#include "glint/render/render.hpp"
#include "glint/sampling/sampler.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"

namespace glint {
namespace {

double mean_image_value(const std::string& sampler_name, std::uint32_t spp, std::uint32_t* spp_taken) {
    RenderFlags overrides;
    overrides.width = 16;
    overrides.height = 12;
    overrides.samples_per_pixel = spp;
    overrides.sampler = sampler_name;
    Scene scene = build_scene(default_scene(), overrides);
    scene.view.settings.threads = 1;
    Film film(16, 12);
    const RenderStats stats = render(scene, film);
    *spp_taken = stats.samples_per_pixel;
    EXPECT_EQ(stats.nonfinite_samples, 0u);
    double sum = 0;
    const Image image = film.to_image();
    for (float v : image.rgb) {
        EXPECT_TRUE(std::isfinite(v));
        sum += v;
    }
    return sum / static_cast<double>(image.rgb.size());
}

TEST(SamplersInRender, EverySamplerRendersTheSameImage) {
    std::uint32_t taken = 0;
    const double reference = mean_image_value("random", 64, &taken);
    ASSERT_GT(reference, 0.01);
    for (const std::string& name : sampler_table().names()) {
        const double mean = mean_image_value(name, 16, &taken);
        EXPECT_EQ(taken, 16u) << name;
        EXPECT_NEAR(mean, reference, 0.03 * reference) << name;
    }
}

}  // namespace
}  // namespace glint
