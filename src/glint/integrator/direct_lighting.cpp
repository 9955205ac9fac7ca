#include "glint/integrator/direct_lighting.hpp"

#include "glint/world/world.hpp"

namespace glint {

Hit facing(const Hit& hit, const Vec3& wo) {
    Hit h = hit;
    h.shading_normal = face_forward(hit.shading_normal, wo);
    return h;
}

bool shadowed(const World& world, const Hit& hit, const LightSample& ls, RayCounters& rays) {
    ++rays.shadow;
    return ls.infinite ? world.occluded(spawn_ray(hit, ls.wi), kInf)
                       : world.occluded(spawn_ray_to(hit, ls.position), kShadowRayEnd);
}

Rgb direct_lighting(const World& world, const Hit& hit, const Bsdf& bsdf, const Vec3& wo,
                    SampleStream& samples, RayCounters& rays) {
    const Rgb ambient_reflectance = bsdf.ambient_reflectance();
    Rgb radiance = ambient_reflectance * world.ambient;
    const Hit at = facing(hit, wo);
    const Vec3& n = at.shading_normal;
    for (const auto& light : world.lights) {
        const int count = light->samples();
        Rgb sum;
        for (int i = 0; i < count; ++i) {
            const Point2 u = samples.next_2d();
            const std::optional<LightSample> ls = light->sample(at, u);
            if (!ls || ls->radiance.is_black() || ls->pdf <= 0) {
                continue;
            }
            if (ls->ambient) {  // an ambient-occlusion probe: the ambient term, if unblocked
                const Rgb reflected = ambient_reflectance * ls->radiance;
                if (!reflected.is_black() && !shadowed(world, at, *ls, rays)) {
                    sum += reflected;
                }
                continue;
            }
            const double cos_theta = dot(n, ls->wi);  // Lambert's cosine law (errata to eq. 14)
            if (cos_theta <= 0) {
                continue;
            }
            const Rgb f = bsdf.evaluate(wo, ls->wi);
            if (f.is_black()) {
                continue;
            }
            if (!shadowed(world, at, *ls, rays)) {
                sum += f * ls->radiance * (cos_theta / ls->pdf);
            }
        }
        radiance += count == 1 ? sum : sum / count;
    }
    return radiance;
}

}  // namespace glint
