#include "glint/integrator/path.hpp"

#include "glint/integrator/direct_lighting.hpp"
#include "glint/integrator/whitted.hpp"
#include "glint/world/world.hpp"

namespace glint {

namespace {
// Russian roulette, after kRouletteStart bounces, ends only paths whose throughput has fallen below
// kRouletteThroughput, with survival probability throughput / kRouletteThroughput. pbrt-v4 lets a
// path survive with probability equal to its throughput; on rtiow-final that costs 2x the MSE for a
// 13 % saving in time, on smallpt's scene the same efficiency; 1/4 is as efficient as no roulette on
// the first and ~6 % better than pbrt's rule on the second (64 spp, against 2048/4096-spp references).
// Paths that never lose throughput (between mirrors) end at max_depth.
constexpr int kRouletteStart = 3;
constexpr double kRouletteThroughput = 0.25;
}  // namespace

std::unique_ptr<Integrator> PathIntegrator::prepared(const World& world, const Camera& camera,
                                                     FilmSize film) const {
    if (!learn_light_visibility_) {
        return nullptr;
    }
    auto visibility =
        std::make_shared<LightVisibility>(LightVisibility::learn(world, camera, film, max_depth_));
    if (!visibility->any()) {
        return nullptr;
    }
    auto copy = std::make_unique<PathIntegrator>(*this);
    copy->visibility_ = std::move(visibility);
    return copy;
}

std::optional<LightSample> PathIntegrator::light_sample_of(const World& world, std::size_t index,
                                                           const Hit& at, Point2 u) const {
    const Light& light = *world.lights[index];
    return visibility_ ? visibility_->sample(index, light, at, u) : light.sample(at, u);
}

double PathIntegrator::light_pdf_of(const World& world, std::size_t index, const Hit& at, const Vec3& wi,
                                    const Hit* on_light) const {
    const Light& light = *world.lights[index];
    return visibility_ ? visibility_->pdf(index, light, at, wi, on_light) : light.pdf(at, wi, on_light);
}

Rgb PathIntegrator::radiance(const World& world, const Ray& camera_ray, SampleStream& samples,
                             RayCounters& rays) const {
    ++rays.camera;
    Rgb radiance;
    Rgb throughput(1.0);
    Ray ray = camera_ray;
    bool specular = true;  // the last bounce was a delta lobe (or the camera): emission counts in full
    double bsdf_pdf = 0;   // solid-angle density of the last BSDF sample
    // This bounce's hit and the last vertex (facing the way the path came): two records that trade
    // places each bounce, since copying a 112-byte Hit, and a facing copy of it, cost ~45 instructions
    // a vertex (2 % of the Cornell box).
    Hit records[2];
    Hit* last = &records[0];
    Hit* current = &records[1];

    for (int bounce = 0;; ++bounce) {
        Hit& hit = *current;
        hit = Hit{};
        const Hit& previous = *last;
        if (!world.intersect(ray, kInf, hit)) {
            const Vec3 dir = normalize(ray.direction);
            const Rgb sky = world.escaped(dir);
            if (specular || !world.environment || !world.environment->worth_sampling_in_paths()) {
                radiance += throughput * sky;
            } else {
                radiance += throughput * sky *
                            power_heuristic(bsdf_pdf, world.environment->pdf(previous, dir, nullptr));
            }
            break;
        }
        const Material& material = world.material(hit);
        throughput *= segment_transmittance(material, hit, ray);
        const Vec3 wo = normalize(-ray.direction);

        const Rgb emitted = material.emitted(hit, wo);
        if (!emitted.is_black()) {
            const std::int32_t light_index = world.light_index_of(hit);
            if (specular || light_index < 0) {
                radiance += throughput * emitted;
            } else {
                const auto index = static_cast<std::size_t>(light_index);
                const double light_pdf = light_pdf_of(world, index, previous, -wo, &hit);
                radiance += throughput * emitted * power_heuristic(bsdf_pdf, light_pdf);
            }
        }
        if (bounce >= max_depth_) {
            break;
        }

        const Bsdf bsdf = material.bsdf(hit);  // the textures, looked up once for all that follows
        // wo in the shading frame, turned once for the light samples' f and pdf and the BSDF sample.
        const Vec3 wo_local = bsdf.frame().to_local(wo);

        // Next-event estimation: one sample of each light worth sampling (see
        // Light::worth_sampling_in_paths).
        // From here on the hit faces wo, as Light::sample expects (the cosines below take |·|, and the
        // BSDF has its frame already).
        hit.shading_normal = face_forward(hit.shading_normal, wo);
        const Hit& at = hit;
        for (std::size_t index = 0; index < world.lights.size(); ++index) {
            const Light& light = *world.lights[index];
            if (!light.physical() || !light.worth_sampling_in_paths()) {
                continue;
            }
            const Point2 u = samples.next_2d();
            const std::optional<LightSample> ls = light_sample_of(world, index, at, u);
            if (!ls || ls->radiance.is_black() || ls->pdf <= 0) {
                continue;
            }
            const Vec3 wi_local = bsdf.frame().to_local(ls->wi);
            const Rgb f = bsdf.evaluate_local(wo_local, wi_local);
            const double cos_theta = std::abs(dot(at.shading_normal, ls->wi));
            if (f.is_black() || cos_theta == 0) {
                continue;
            }
            const double weight =
                ls->delta ? 1.0 : power_heuristic(ls->pdf, bsdf.pdf_local(wo_local, wi_local));
            if (weight > 0 && !shadowed(world, at, *ls, rays)) {
                radiance += throughput * f * ls->radiance * (cos_theta * weight / ls->pdf);
            }
        }

        // Continue the path by sampling the BSDF.
        const std::optional<BsdfSample> s = bsdf.sample_from_local(wo_local, samples.next_2d());
        if (!s || s->pdf <= 0 || s->f.is_black()) {
            break;
        }
        throughput *= s->f * (std::abs(dot(hit.shading_normal, s->wi)) / s->pdf);
        specular = s->delta;
        bsdf_pdf = s->pdf;
        std::swap(last, current);

        if (bounce + 1 >= kRouletteStart) {
            // Drawn whatever the survival, so that each bounce reads the same sample dimensions.
            const double survival = std::min(1.0, throughput.max_component() / kRouletteThroughput);
            if (samples.next_1d() >= survival) {
                break;
            }
            throughput = throughput / survival;
        }
        ++rays.secondary;
        ray = spawn_ray(hit, s->wi);
    }
    return radiance;
}

}  // namespace glint
