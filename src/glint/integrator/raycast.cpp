#include "glint/integrator/raycast.hpp"

#include "glint/integrator/direct_lighting.hpp"
#include "glint/world/world.hpp"

namespace glint {

Rgb RaycastIntegrator::radiance(const World& world, const Ray& ray, SampleStream& samples,
                                RayCounters& rays) const {
    ++rays.camera;
    Hit hit;
    if (!world.intersect(ray, kInf, hit)) {
        return world.escaped(ray.direction);
    }
    const Material& material = world.material(hit);
    const Vec3 wo = normalize(-ray.direction);
    return material.emitted(hit, wo) + direct_lighting(world, hit, material.bsdf(hit), wo, samples, rays);
}

}  // namespace glint
