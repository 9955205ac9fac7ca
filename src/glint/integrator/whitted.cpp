#include "glint/integrator/whitted.hpp"

#include "glint/integrator/direct_lighting.hpp"
#include "glint/scene/scene.hpp"

namespace glint {

Rgb segment_transmittance(const Material& material, const Hit& hit, const Ray& ray) {
    if (dot(ray.direction, hit.normal) <= 0) {
        return Rgb(1.0);  // arrived from outside: the segment ran through air
    }
    const Rgb sigma = material.absorption();
    return sigma.is_black() ? Rgb(1.0) : beer_transmittance(sigma, hit.t * length(ray.direction));
}

Rgb WhittedIntegrator::radiance(const Scene& scene, const Ray& ray, SampleStream& samples,
                                RayCounters& rays) const {
    ++rays.camera;
    return trace(scene, ray, 0, 1.0, samples, rays);
}

Rgb WhittedIntegrator::trace(const Scene& scene, const Ray& ray, int depth, double weight,
                             SampleStream& samples, RayCounters& rays) const {
    Hit hit;
    if (!scene.intersect(ray, kInf, hit)) {
        return scene.escaped(ray.direction);
    }
    const Material& material = scene.material(hit);
    const Vec3 wo = normalize(-ray.direction);
    Rgb radiance = material.emitted(hit, wo) + direct_lighting(scene, hit, material, wo, samples, rays);

    if (depth < max_depth_) {
        // The perfect-specular lobes: a BsdfSample's pdf for a delta lobe is the probability of
        // choosing it, so f·|cos| is that lobe's share of the light (the Fresnel reflectance R for
        // reflection, 1 − R for refraction). Asking with u.x at both ends of [0, 1) finds both
        // lobes of a dielectric, which are then both traced: Whitted's deterministic split.
        const std::optional<BsdfSample> first = material.sample(hit, wo, {0.0, 0.5});
        const std::optional<BsdfSample> second = material.sample(hit, wo, {1.0 - 0x1p-53, 0.5});
        const auto follow = [&](const BsdfSample& s, const Rgb& lobe_weight) {
            const double branch_weight = weight * lobe_weight.max_component();
            if (!(branch_weight >= kMinBranchWeight)) {
                return;
            }
            ++rays.secondary;
            radiance +=
                lobe_weight * trace(scene, spawn_ray(hit, s.wi), depth + 1, branch_weight, samples, rays);
        };
        const bool two_lobes = !material.random_delta_direction() && first && second && first->delta &&
                               second->delta && first->wi != second->wi;
        if (two_lobes) {
            follow(*first, first->f * std::abs(dot(hit.shading_normal, first->wi)));
            follow(*second, second->f * std::abs(dot(hit.shading_normal, second->wi)));
        } else if ((first && first->delta) || (second && second->delta)) {
            // One delta lobe (a mirror, total internal reflection), or a material that chooses its
            // lobe otherwise: one sample with the path's own random numbers, weighted f·|cos|/pdf.
            const std::optional<BsdfSample> s = material.sample(hit, wo, samples.next_2d());
            if (s && s->delta && s->pdf > 0) {
                follow(*s, s->f * (std::abs(dot(hit.shading_normal, s->wi)) / s->pdf));
            }
        }
    }
    return radiance * segment_transmittance(material, hit, ray);
}

}  // namespace glint
