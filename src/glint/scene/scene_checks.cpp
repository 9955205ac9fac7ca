#include "glint/scene/scene_checks.hpp"

#include <algorithm>

#include "glint/integrator/path.hpp"
#include "glint/integrator/raycast.hpp"
#include "glint/material/material.hpp"

namespace glint {
namespace {

bool black(const Rgb& c) {
    return c.r <= 0 && c.g <= 0 && c.b <= 0;
}

// Whether the material scatters only into mirror or refraction directions (a delta lobe): probed by
// sampling it at normal incidence, as an integrator would at a hit.
bool only_delta_lobes(const Material& material) {
    Hit hit;
    hit.normal = hit.shading_normal = {0, 0, 1};
    hit.uv = {0.5, 0.5};
    const Bsdf bsdf = material.bsdf(hit);
    bool scatters = false;  // a material that scatters nothing (an emitter, black) is not a mirror
    for (const Point2 u : {Point2{0.1, 0.3}, Point2{0.6, 0.8}, Point2{0.9, 0.1}}) {
        const std::optional<BsdfSample> sample = bsdf.sample({0, 0, 1}, u);
        if (sample && !sample->delta) {
            return false;
        }
        scatters = scatters || sample.has_value();
    }
    return scatters;
}

}  // namespace

std::vector<std::string> scene_warnings(const Scene& scene) {
    std::vector<std::string> warnings;
    const World& world = *scene.world;
    const bool lit =
        !world.lights.empty() || world.environment || !black(world.ambient) || !black(world.background);
    if (!lit) {
        warnings.push_back(
            "the scene has no light: no light source, no emissive surface, no environment and a black "
            "background, so the image will be black; add one under `lights:` or give a surface an `emissive` "
            "material (docs/scene-format.md)");
    }
    const auto* path = dynamic_cast<const PathIntegrator*>(scene.view.integrator.get());
    if (lit && path != nullptr && !path->samples_lights()) {
        // Without light samples, light is found only where a BSDF sample meets an emitter or the sky.
        const bool found_by_bsdf_samples =
            world.environment || !black(world.background) ||
            std::any_of(world.shape_lights.begin(), world.shape_lights.end(),
                        [](std::int32_t light) { return light >= 0; });  // a shape that is a light
        if (!found_by_bsdf_samples) {
            warnings.push_back(
                "the path integrator with `sample_lights: false` finds light only where its rays meet an "
                "emitter or the sky, never a point, spot or directional light, and the scene has no other "
                "light, so the image will be black; leave `sample_lights` on (docs/scene-format.md)");
        }
    }
    if (dynamic_cast<const RaycastIntegrator*>(scene.view.integrator.get())) {
        const bool any_delta = std::any_of(world.materials.begin(), world.materials.end(),
                                           [](const auto& m) { return m && only_delta_lobes(*m); });
        if (any_delta) {
            warnings.push_back(
                "the scene has mirror or glass surfaces, which the raycast integrator (the default) does not "
                "follow: they render black; use --integrator whitted (the paper's) or --integrator path");
        }
    }
    return warnings;
}

bool all_black(const Image& image) {
    return std::all_of(image.rgb.begin(), image.rgb.end(), [](float v) { return v == 0; });
}

}  // namespace glint
