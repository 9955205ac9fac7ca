#include "glint/integrator/raycast.hpp"

#include "glint/integrator/direct_lighting.hpp"
#include "glint/scene/scene.hpp"

namespace glint {

Rgb RaycastIntegrator::radiance(const Scene& scene, const Ray& ray, SampleStream& samples,
                                RayCounters& rays) const {
    ++rays.camera;
    Hit hit;
    if (!scene.intersect(ray, kInf, hit)) {
        return scene.escaped(ray.direction);
    }
    const Material& material = scene.material(hit);
    const Vec3 wo = normalize(-ray.direction);
    return material.emitted(hit, wo) + direct_lighting(scene, hit, material, wo, samples, rays);
}

}  // namespace glint
