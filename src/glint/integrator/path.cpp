#include "glint/integrator/path.hpp"

#include <algorithm>
#include <cassert>

#include "glint/core/fixed_vector.hpp"
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
    if (!options_.sample_lights || !options_.learn_light_visibility) {
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

// A path's state from bounce to bounce. It holds its two Hit records, to which it refers, so it is
// built where it stays, never copied. (The state kept apart from the records, so that a loop could
// hold it in registers, ran 3 % slower on RTIOW's final scene.)
struct PathIntegrator::Path {
    Path(const Ray& camera_ray, SampleStream& stream) : ray(camera_ray), samples(&stream) {}
    Path(const Path&) = delete;
    Path& operator=(const Path&) = delete;

    Ray ray;  // this bounce's
    SampleStream* samples;
    Rgb radiance;
    Rgb throughput{1.0};
    // What this bounce's ray meets counts in full, with no MIS weight: no light sample could have found
    // it, since the last bounce was a delta lobe (or the camera's ray), or the lights are not sampled.
    bool counts_in_full = true;
    bool found = false;  // whether this bounce's ray hit anything (in *current)
    int bounce = 0;
    double bsdf_pdf = 0;  // solid-angle density of the last BSDF sample
    // This bounce's hit and the last vertex (facing the way the path came): two records that trade
    // places each bounce, since copying a 112-byte Hit, and a facing copy of it, cost ~45 instructions
    // a vertex (2 % of the Cornell box).
    // Both start as plain storage (a union, not a Hit{} to clear): each trace clears the record it fills
    // (trace(), trace_together()), and the last one is read only after a bounce (for MIS, when what
    // that bounce's ray meets does not count in full), when it is a record filled there. Clearing them here
    // as well cost RTIOW's final scene 1.6 % of its time.
    union Record {
        Record() {}
        Hit hit;
    };
    Record records[2];
    Hit* last = &records[0].hit;
    Hit* current = &records[1].hit;
};

// Both inlined into radiance's and radiances' loops: one loop, as before the two were split, with no
// call per bounce.
__attribute__((always_inline)) inline void PathIntegrator::trace(const World& world, Path& path) const {
    *path.current = Hit{};
    path.found = world.intersect(path.ray, kInf, *path.current);
}

__attribute__((always_inline)) inline bool PathIntegrator::shade(const World& world, Path& path,
                                                                 RayCounters& rays) const {
    Rgb& radiance = path.radiance;
    Rgb& throughput = path.throughput;
    const Ray& ray = path.ray;
    Hit& hit = *path.current;
    const Hit& previous = *path.last;
    // A path's rays have unit directions: the camera's (camera.hpp, tests/camera/all_cameras_test.cpp)
    // and the BSDF samples' (tests/material/bsdf_test.cpp). So the direction serves as it is, for the
    // sky and for wo. Normalised again at every vertex (and once more in the sky), it cost a square
    // root and a division each time and changed no bit of any example: without them, bench/ab.py gave
    // RTIOW's final scene 0.987 of the time, the Cornell box 0.975, smallpt's scene 0.983.
    if (!path.found) {
        const Vec3& dir = ray.direction;
        const Rgb sky = world.escaped(dir);
        if (path.counts_in_full || !world.environment || !world.environment->worth_sampling_in_paths()) {
            radiance += throughput * sky;
        } else {
            radiance += throughput * sky *
                        power_heuristic(path.bsdf_pdf, world.environment->pdf(previous, dir, nullptr));
        }
        return false;
    }
    const Material& material = world.material(hit);
    attenuate_along_segment(throughput, material, hit, ray);
    const Vec3 wo = -ray.direction;

    const Rgb emitted = material.emitted(hit, wo);
    if (!emitted.is_black()) {
        const std::int32_t light_index = world.light_index_of(hit);
        if (path.counts_in_full || light_index < 0) {
            radiance += throughput * emitted;
        } else {
            const auto index = static_cast<std::size_t>(light_index);
            const double light_pdf = light_pdf_of(world, index, previous, -wo, &hit);
            radiance += throughput * emitted * power_heuristic(path.bsdf_pdf, light_pdf);
        }
    }
    if (path.bounce >= max_depth_) {
        return false;
    }

    // The textures, looked up once for all that follows. Lambert's lobe of a constant reflectance (every
    // wall of the Cornell boxes and of smallpt's room, most of RTIOW's spheres) inline, without the
    // Bsdf's virtual calls: the same bits, the Cornell box in 0.97 of the time, smallpt's scene 0.98.
    if (const Rgb* rho = material.constant_lambert()) {
        return scatter(world, path, rays, LambertBsdf(Frame::from_normal(hit.shading_normal), *rho), wo);
    }
    return scatter(world, path, rays, material.bsdf(hit), wo);
}

// The rest of shade() once the BSDF is made: next-event estimation and the next bounce. BsdfAtHit is
// Bsdf or LambertBsdf (the same interface in the shading frame). A call, not inlined into shade()'s
// three copies: that is how it was measured (GCC had set aside an always_inline here, which came
// after the first use).
template <class BsdfAtHit>
__attribute__((noinline)) bool PathIntegrator::scatter(const World& world, Path& path, RayCounters& rays,
                                                       const BsdfAtHit& bsdf, const Vec3& wo) const {
    Rgb& radiance = path.radiance;
    Rgb& throughput = path.throughput;
    SampleStream& samples = *path.samples;
    Hit& hit = *path.current;
    // wo in the shading frame, turned once for the light samples' f and pdf and the BSDF sample.
    const Vec3 wo_local = bsdf.frame().to_local(wo);

    // Next-event estimation: one sample of each light worth sampling (see
    // Light::worth_sampling_in_paths).
    // From here on the hit faces wo, as Light::sample expects (the cosines below take |·|, and the
    // BSDF has its frame already).
    hit.shading_normal = face_forward(hit.shading_normal, wo);
    const Hit& at = hit;
    const std::size_t lights_to_sample = options_.sample_lights ? world.lights.size() : 0;
    for (std::size_t index = 0; index < lights_to_sample; ++index) {
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
        // The MIS weight over the light's density (the estimator's 1/pdf taken with it).
        const double weight_over_pdf =
            ls->delta ? 1 / ls->pdf : power_heuristic_over_pdf(ls->pdf, bsdf.pdf_local(wo_local, wi_local));
        if (weight_over_pdf > 0 && !shadowed(world, at, *ls, rays)) {
            radiance += throughput * f * ls->radiance * (cos_theta * weight_over_pdf);
        }
    }

    // Continue the path by sampling the BSDF.
    const std::optional<BsdfSample> s = bsdf.sample_from_local(wo_local, samples.next_2d());
    if (!s || s->pdf <= 0 || s->f.is_black()) {
        return false;
    }
    throughput *= s->weight;
    path.counts_in_full = s->delta || !options_.sample_lights;
    path.bsdf_pdf = s->pdf;
    std::swap(path.last, path.current);

    if (path.bounce + 1 >= kRouletteStart) {
        // Drawn whatever the survival, so that each bounce reads the same sample dimensions.
        const double survival = std::min(1.0, throughput.max_component() / kRouletteThroughput);
        if (samples.next_1d() >= survival) {
            return false;
        }
        throughput = throughput / survival;
    }
    ++rays.secondary;
    path.ray = spawn_ray(hit, s->wi);
    ++path.bounce;
    return true;
}

void PathIntegrator::trace_together(const World& world, std::span<Path* const> paths) const {
    assert(paths.size() <= kPathsTogether);
    // Zeroed, since GCC cannot see that intersect_packet reads only the first paths.size() entries.
    const Ray* rays[kPathsTogether] = {};
    Hit* hits[kPathsTogether] = {};
    bool found[kPathsTogether];
    for (std::size_t k = 0; k < paths.size(); ++k) {
        *paths[k]->current = Hit{};
        rays[k] = &paths[k]->ray;
        hits[k] = paths[k]->current;
    }
    world.intersect_packet(rays, static_cast<int>(paths.size()), kInf, hits, found);
    for (std::size_t k = 0; k < paths.size(); ++k) {
        paths[k]->found = found[k];
    }
}

Rgb PathIntegrator::radiance(const World& world, const Ray& camera_ray, SampleStream& samples,
                             RayCounters& rays) const {
    ++rays.camera;
    Path path(camera_ray, samples);
    do {
        trace(world, path);
    } while (shade(world, path, rays));
    return path.radiance;
}

void PathIntegrator::radiances(const World& world, std::span<const Ray> camera_rays,
                               std::span<SampleStream> streams, RayCounters& rays, std::span<Rgb> out) const {
    assert(streams.size() == camera_rays.size() && out.size() == camera_rays.size());
    // Paths a few at a time, on the stack (the render loop hands at most 16).
    for (std::size_t start = 0; start < camera_rays.size(); start += kPathsTogether) {
        const std::size_t count = std::min(kPathsTogether, camera_rays.size() - start);
        FixedVector<Path, kPathsTogether> paths;
        Path* traced[kPathsTogether];  // the paths whose current ray has been traced, to go on with
        for (std::size_t i = 0; i < count; ++i) {
            ++rays.camera;
            traced[i] = &paths.emplace_back(camera_rays[start + i], streams[start + i]);
        }
        // The camera rays together: they leave one pixel (or a few neighbours) in much the same direction, so
        // an accelerator may trace them as one packet (BvhAccelerator does for trees of spheres).
        std::span<Path*> going_on(traced, count);
        trace_together(world, going_on);
        if (world.traces_packets()) {
            // Their first bounces together too: they leave the points that one pixel's camera rays
            // found, so they start together, and part only on the way (RTIOW's final scene: 0.956 of the
            // time, bench/ab.py). The later bounces part at once, and gain nothing from it: their
            // packets, every path's bounce in step with the others', were no faster. Nor was this one
            // with an accelerator that traces rays one at a time (the Cornell box's flat list: 1.028).
            std::size_t bouncing = 0;
            for (Path* path : going_on) {
                if (shade(world, *path, rays)) {
                    going_on[bouncing++] = path;
                }
            }
            going_on = going_on.first(bouncing);
            trace_together(world, going_on);
        }
        for (Path* path : going_on) {
            while (shade(world, *path, rays)) {
                trace(world, *path);
            }
        }
        for (std::size_t i = 0; i < count; ++i) {
            out[start + i] = paths[i].radiance;
        }
    }
}

}  // namespace glint
