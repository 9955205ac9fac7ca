#include "glint/integrator/whitted.hpp"

#include <array>
#include <vector>

#include "glint/integrator/direct_lighting.hpp"
#include "glint/world/world.hpp"

namespace glint {

// The recursion of Whitted's model, L(ray) = T · (Le + direct + Σ lobe · L(branch)), is run as a loop
// over an explicit stack of pending branches, in the order the recursion would take them (a node, its
// first branch's whole subtree, then its second), so the random numbers go to the same places. A
// recursive version overflowed the stack of a worker thread at depths of a few thousand; this one needs
// one pending entry per level at most. The stack is per thread and reused, so no allocation per ray.
Rgb WhittedIntegrator::radiance(const World& world, const Ray& camera_ray, SampleStream& samples,
                                RayCounters& rays) const {
    ++rays.camera;
    struct Branch {
        Ray ray;
        int depth;
        double weight;   // the largest channel of the product of the lobe weights from the camera
        Rgb throughput;  // what this branch's radiance is multiplied by on its way to the camera
    };
    thread_local std::vector<Branch> pending;
    pending.clear();
    pending.push_back({camera_ray, 0, 1.0, Rgb(1.0)});
    Rgb radiance;
    while (!pending.empty()) {
        const Branch branch = pending.back();
        pending.pop_back();
        const Ray& ray = branch.ray;
        Hit hit;
        if (!world.intersect(ray, kInf, hit)) {
            radiance += branch.throughput * world.escaped(ray.direction);
            continue;
        }
        const Material& material = world.material(hit);
        const Vec3 wo = normalize(-ray.direction);
        Rgb throughput = branch.throughput;
        attenuate_along_segment(throughput, material, hit, ray);
        const Bsdf bsdf = material.bsdf(hit);  // the textures, looked up once for all that follows
        radiance +=
            throughput * (material.emitted(hit, wo) + direct_lighting(world, hit, bsdf, wo, samples, rays));
        if (branch.depth >= max_depth_) {
            continue;
        }
        // The perfect-specular lobes: a BsdfSample's pdf for a delta lobe is the probability of
        // choosing it, so f·|cos| is that lobe's share of the light (the Fresnel reflectance R for
        // reflection, 1 − R for refraction). Asking with u.x at both ends of [0, 1) finds both
        // lobes of a dielectric, which are then both traced: Whitted's deterministic split.
        const std::optional<BsdfSample> first = bsdf.sample(wo, {0.0, 0.5});
        const std::optional<BsdfSample> second = bsdf.sample(wo, {1.0 - 0x1p-53, 0.5});
        // Branches to follow, at most two, in the order they are traced.
        std::array<Branch, 2> next;
        int count = 0;
        const auto follow = [&](const BsdfSample& s, const Rgb& lobe_weight) {
            const double branch_weight = branch.weight * lobe_weight.max_component();
            if (!(branch_weight >= kMinBranchWeight)) {
                return;
            }
            ++rays.secondary;
            next[static_cast<size_t>(count++)] = {spawn_ray(hit, s.wi), branch.depth + 1, branch_weight,
                                                  throughput * lobe_weight};
        };
        const bool two_lobes = !material.random_delta_direction() && first && second && first->delta &&
                               second->delta && first->wi != second->wi;
        if (two_lobes) {
            follow(*first, first->f * std::abs(dot(hit.shading_normal, first->wi)));
            follow(*second, second->f * std::abs(dot(hit.shading_normal, second->wi)));
        } else if ((first && first->delta) || (second && second->delta)) {
            // One delta lobe (a mirror, total internal reflection), or a material that chooses its
            // lobe otherwise: one sample with the path's own random numbers, weighted f·|cos|/pdf.
            const std::optional<BsdfSample> s = bsdf.sample(wo, samples.next_2d());
            if (s && s->delta && s->pdf > 0) {
                follow(*s, s->weight);
            }
        }
        // Pushed in reverse, so that the first branch and all it leads to are traced first.
        for (int i = count - 1; i >= 0; --i) {
            pending.push_back(next[static_cast<size_t>(i)]);
        }
    }
    return radiance;
}

}  // namespace glint
