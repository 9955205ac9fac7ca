// The built world: what integrators see. Shapes, their materials, the lights, the accelerator over the
// shapes and what rays that escape meet. No camera, no render settings: those are the view
// (render/view.hpp), so that moving the camera or changing the sample count never rebuilds geometry.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "glint/accel/accelerator.hpp"
#include "glint/light/light.hpp"
#include "glint/material/material.hpp"

namespace glint {

struct World {
    // Shapes are shared, and never changed once built, so that a rebuilt world (a material edit in
    // `glint serve`) can reuse them and the accelerator over them.
    std::vector<std::shared_ptr<const Shape>> shapes;
    std::vector<std::uint32_t> shape_materials;  // material index of shapes[i]
    std::vector<std::unique_ptr<Material>> materials;
    std::vector<std::unique_ptr<Light>> lights;
    std::shared_ptr<const Accelerator> accelerator;
    Rgb background;
    Rgb ambient;  // the sum of the ambient lights' radiance
    // The environment light, if the world has one: rays that escape see its radiance instead of
    // `background` (the builder forbids giving both).
    const Light* environment = nullptr;
    // The area light each shape is (index into `lights`), or -1: the path tracer needs a hit
    // emitter's light for multiple importance sampling.
    std::vector<std::int32_t> shape_lights;

    bool intersect(const Ray& ray, double t_max, Hit& hit) const {
        return accelerator->intersect(ray, t_max, hit);
    }
    void intersect_packet(const Ray* const* rays, int n, double t_max, Hit* const* hits, bool* found) const {
        accelerator->intersect_packet(rays, n, t_max, hits, found);
    }
    bool traces_packets() const { return accelerator->traces_packets(); }
    bool occluded(const Ray& ray, double t_max) const { return accelerator->occluded(ray, t_max); }
    const Material& material(const Hit& hit) const { return *materials[shape_materials[hit.primitive]]; }
    // Radiance seen along a ray that leaves the world in direction `dir`.
    Rgb escaped(const Vec3& dir) const { return environment ? environment->escaped(dir) : background; }
    // The index in `lights` of the light a hit surface belongs to (an emitting shape), or -1.
    std::int32_t light_index_of(const Hit& hit) const {
        return hit.primitive < shape_lights.size() ? shape_lights[hit.primitive] : -1;
    }
    // The light a hit surface belongs to, or nullptr.
    const Light* light_of(const Hit& hit) const {
        const std::int32_t i = light_index_of(hit);
        return i < 0 ? nullptr : lights[static_cast<std::size_t>(i)].get();
    }
};

// Gives shape `shape` (an index into world.shapes) the material `material` (an index into
// world.materials). An emitting material makes the shape an area light, so that light sampling finds it:
// the one place where that happens, for the scene builder and for tests that change a material alike.
// Returns false, changing nothing, when the material emits and the shape has no finite area.
bool attach_material(World& world, std::size_t shape, std::uint32_t material);

}  // namespace glint
