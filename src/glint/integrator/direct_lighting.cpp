#include "glint/integrator/direct_lighting.hpp"

#include "glint/scene/scene.hpp"

namespace glint {

// A shadow ray stops this short of the light's point, so the light's own surface (for lights with one)
// does not shadow itself; relative, so it holds at any scene scale.
constexpr double kShadowRayEnd = 1.0 - 1e-9;

Rgb direct_lighting(const Scene& scene, const Hit& hit, const Material& material, const Vec3& wo,
                    SampleStream& samples, RayCounters& rays) {
    Rgb radiance = material.ambient_reflectance(hit) * scene.ambient;
    const Vec3 n = face_forward(hit.shading_normal, wo);
    for (const auto& light : scene.lights) {
        const Point2 u = samples.next_2d();
        const std::optional<LightSample> ls = light->sample(hit, u);
        if (!ls || ls->radiance.is_black() || ls->pdf <= 0) {
            continue;
        }
        const double cos_theta = dot(n, ls->wi);  // Lambert's cosine law (errata to eq. 14)
        if (cos_theta <= 0) {
            continue;
        }
        const Rgb f = material.evaluate(hit, wo, ls->wi);
        if (f.is_black()) {
            continue;
        }
        ++rays.shadow;
        const bool blocked = ls->infinite ? scene.occluded(spawn_ray(hit, ls->wi), kInf)
                                          : scene.occluded(spawn_ray_to(hit, ls->position), kShadowRayEnd);
        if (!blocked) {
            radiance += f * ls->radiance * (cos_theta / ls->pdf);
        }
    }
    return radiance;
}

}  // namespace glint
