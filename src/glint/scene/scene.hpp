// A built scene: what the renderer sees. No YAML, no names to resolve, everything checked.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/accel/accelerator.hpp"
#include "glint/camera/camera.hpp"
#include "glint/light/light.hpp"
#include "glint/material/material.hpp"
#include "glint/world/settings.hpp"

namespace glint {

struct Scene {
    RenderSettings settings;
    std::unique_ptr<Camera> camera;
    std::vector<std::unique_ptr<Shape>> shapes;
    std::vector<std::uint32_t> shape_materials;  // material index of shapes[i]
    std::vector<std::unique_ptr<Material>> materials;
    std::vector<std::unique_ptr<Light>> lights;
    std::unique_ptr<Accelerator> accelerator;
    Rgb background;
    Rgb ambient;  // the sum of the ambient lights' radiance
    // The environment light, if the scene has one: rays that escape see its radiance instead of
    // `background` (the builder forbids giving both).
    const Light* environment = nullptr;
    // The area light each shape is (index into `lights`), or -1: the path tracer needs a hit
    // emitter's light for multiple importance sampling.
    std::vector<std::int32_t> shape_lights;

    bool intersect(const Ray& ray, double t_max, Hit& hit) const {
        return accelerator->intersect(ray, t_max, hit);
    }
    bool occluded(const Ray& ray, double t_max) const { return accelerator->occluded(ray, t_max); }
    const Material& material(const Hit& hit) const { return *materials[shape_materials[hit.primitive]]; }
    // Radiance seen along a ray that leaves the scene in direction `dir`.
    Rgb escaped(const Vec3& dir) const { return environment ? environment->escaped(dir) : background; }
    // The light a hit surface belongs to (an emitting shape), or nullptr.
    const Light* light_of(const Hit& hit) const {
        const std::int32_t i = hit.primitive < shape_lights.size() ? shape_lights[hit.primitive] : -1;
        return i < 0 ? nullptr : lights[static_cast<std::size_t>(i)].get();
    }
};

// Settings the command line imposes over the scene file's `render:` block.
struct RenderOverrides {
    std::optional<int> width, height, threads, max_depth;
    std::optional<std::uint32_t> samples_per_pixel;
    std::optional<std::uint64_t> seed;
    std::optional<std::string> sampler, integrator, accelerator;
};

struct SceneDesc;
// Validates the whole description and builds the scene. Throws SceneError at the first mistake.
Scene build_scene(const SceneDesc& desc, const RenderOverrides& overrides = {});

}  // namespace glint
