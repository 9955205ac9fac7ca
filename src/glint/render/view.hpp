// The view: how the world is looked at and rendered. Built by the scene builder from the `camera:` and
// `render:` blocks, apart from the world, so that a camera move or a new sample count (the preview's
// edits, the command line's --set) rebuilds only this.
#pragma once

#include <memory>

#include "glint/camera/camera.hpp"
#include "glint/integrator/integrator.hpp"
#include "glint/sampling/sampler.hpp"
#include "glint/world/settings.hpp"

namespace glint {

struct View {
    RenderSettings settings;
    std::unique_ptr<Camera> camera;
    std::unique_ptr<Sampler> sampler;  // made for settings.samples_per_pixel
    std::unique_ptr<Integrator> integrator;
};

}  // namespace glint
