#include "glint/integrator/whitted.hpp"

#include "glint/integrator/direct_lighting.hpp"
#include "glint/scene/scene.hpp"

namespace glint {

Rgb beer_transmittance(const Rgb& absorption, double distance) {
    if (absorption.is_black()) {
        return Rgb(1.0);
    }
    return {std::exp(-absorption.r * distance), std::exp(-absorption.g * distance),
            std::exp(-absorption.b * distance)};
}

Rgb medium_after(const Material& material, const Hit& hit, const Vec3& wo, const Vec3& wi,
                 const Rgb& current) {
    const double side_out = dot(hit.normal, wo);
    const double side_in = dot(hit.normal, wi);
    if (side_out * side_in > 0) {
        return current;  // reflected: still in the same medium
    }
    return side_in < 0 ? material.absorption(hit) : Rgb{};  // into the object, or out into air
}

Rgb WhittedIntegrator::radiance(const Scene& scene, const Ray& ray, SampleStream& samples,
                                RayCounters& rays) const {
    ++rays.camera;
    return trace(scene, ray, 0, Rgb{}, 1.0, samples, rays);
}

Rgb WhittedIntegrator::trace(const Scene& scene, const Ray& ray, int depth, const Rgb& absorption,
                             double weight, SampleStream& samples, RayCounters& rays) const {
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
            const Rgb medium = medium_after(material, hit, wo, s.wi, absorption);
            radiance += lobe_weight *
                        trace(scene, spawn_ray(hit, s.wi), depth + 1, medium, branch_weight, samples, rays);
        };
        const bool two_lobes = first && second && first->delta && second->delta && first->wi != second->wi;
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
    return radiance * beer_transmittance(absorption, hit.t * length(ray.direction));
}

}  // namespace glint
