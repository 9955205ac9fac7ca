#include "glint/render/render.hpp"

#include <tbb/global_control.h>

#include <algorithm>
#include <cassert>
#include <chrono>
#include <mutex>
#include <optional>

#include "glint/core/fixed_vector.hpp"
#include "glint/render/progressive.hpp"

namespace glint {

FilmAndLens camera_points(const View& view, const SampleHashes& key) {
    return view.sampler->camera_point(key, view.camera->uses_lens());
}

namespace {
// The film point (in pixels) of pixel (x, y)'s sample at `film`, a point of the unit square, after the
// pixel filter.
Point2 film_point(const View& view, Point2 film, int x, int y) {
    const Point2 offset = view.settings.filter.offset(film);
    return {x + offset.x, y + offset.y};
}
}  // namespace

std::optional<Ray> camera_ray(const View& view, const FilmAndLens& points, int x, int y) {
    const Ray ray = view.camera->generate_ray(film_point(view, points.film, x, y), points.lens);
    if (!sees_scene(ray)) {
        return std::nullopt;
    }
    return ray;
}

std::optional<Ray> camera_ray(const View& view, const SampleHashes& key, int x, int y) {
    return camera_ray(view, camera_points(view, key), x, y);
}

Rgb render_sample(const World& world, const View& view, const Integrator& integrator, int x, int y,
                  const SampleHashes& key, RayCounters& rays) {
    return render_sample(world, view, integrator, x, y, key, camera_points(view, key), rays);
}

namespace {
// A sample's radiance as the film takes it: scaled down to the settings' clamp, if any.
Rgb clamped(const View& view, const Rgb& radiance) {
    const double clamp = view.settings.clamp;
    const double peak = std::max({radiance.r, radiance.g, radiance.b});
    if (clamp > 0 && peak > clamp) {  // NaN peaks fail the test and reach the film's non-finite count
        return radiance * (clamp / peak);
    }
    return radiance;
}
}  // namespace

Rgb render_sample(const World& world, const View& view, const Integrator& integrator, int x, int y,
                  const SampleHashes& key, const FilmAndLens& points, RayCounters& rays) {
    const std::optional<Ray> ray = camera_ray(view, points, x, y);
    if (!ray) {
        return Rgb{};  // outside the camera's image (a fisheye's corners): black, nothing traced
    }
    SampleStream stream(*view.sampler, key, kFirstIntegratorDimension);
    return clamped(view, integrator.radiance(world, *ray, stream, rays));
}

void render_batch(const World& world, const View& view, const Integrator& integrator,
                  std::span<const SampleJob> jobs, RayCounters& rays, std::span<Rgb> out) {
    assert(out.size() == jobs.size());
    // A few samples at a time (the render loop hands at most 16). Samples whose camera sees nothing
    // are black and left out of the integrator's call, as render_sample leaves them.
    constexpr std::size_t kTogether = 16;
    for (std::size_t start = 0; start < jobs.size(); start += kTogether) {
        const std::size_t count = std::min(kTogether, jobs.size() - start);
        // The camera makes the chunk's rays together (camera_ray's, for each sample).
        Point2 film[kTogether];
        Point2 lens[kTogether];
        Ray made[kTogether];
        for (std::size_t i = 0; i < count; ++i) {
            const SampleJob& job = jobs[start + i];
            film[i] = film_point(view, job.points.film, job.x, job.y);
            lens[i] = job.points.lens;
        }
        view.camera->generate_rays({film, count}, {lens, count}, {made, count});
        FixedVector<Ray, kTogether> camera_rays;
        FixedVector<SampleStream, kTogether> streams;
        FixedVector<std::size_t, kTogether> sample_of;  // the sample (index into out) of each traced ray
        FixedVector<Rgb, kTogether> radiances;
        for (std::size_t i = start; i < start + count; ++i) {
            out[i] = Rgb{};
            if (const Ray& ray = made[i - start]; sees_scene(ray)) {
                camera_rays.emplace_back(ray);
                streams.emplace_back(*view.sampler, jobs[i].key, kFirstIntegratorDimension,
                                     jobs[i].integrator_points);
                sample_of.emplace_back(i);
                radiances.emplace_back();
            }
        }
        integrator.radiances(world, camera_rays.span(), streams.span(), rays, radiances.span());
        for (std::size_t j = 0; j < sample_of.size(); ++j) {
            out[sample_of[j]] = clamped(view, radiances[j]);
        }
    }
}

Rgb render_sample(const World& world, const View& view, const Integrator& integrator, int x, int y,
                  std::uint32_t sample, RayCounters& rays) {
    const SampleHashes key(SampleHashes::pixel_hash(view.settings.seed, static_cast<std::uint32_t>(x),
                                                    static_cast<std::uint32_t>(y)),
                           sample);
    return render_sample(world, view, integrator, x, y, key, rays);
}

RenderStats render(const World& world, const View& view, Film& film, const RenderCallbacks& callbacks) {
    // Small first passes only for a caller that sees or stops at the ends of passes: a time limit, or a
    // pass_done (checkpoints). A stop_after_pass (Ctrl-C) waits for a pass of at most 16 samples either
    // way, as it always did after the first few.
    const PassSizes passes =
        callbacks.pass_done || callbacks.time_limit_seconds > 0 ? PassSizes::kGrowing : PassSizes::kFull;
    ProgressiveRender progressive(world, view, film, passes);
    std::optional<tbb::global_control> thread_limit;
    if (view.settings.threads > 0) {
        thread_limit.emplace(tbb::global_control::max_allowed_parallelism,
                             static_cast<size_t>(view.settings.threads));
    }
    const PixelWindow window = view.settings.rendered_window();
    if (callbacks.resume_after_samples > 0) {
        progressive.resume_after(callbacks.resume_after_samples);
    }
    const double pixels = static_cast<double>(window.width()) * window.height();
    const double total_work = pixels * progressive.target_samples();
    std::atomic<std::uint64_t> work_done{static_cast<std::uint64_t>(pixels * progressive.samples_done())};
    std::mutex progress_mutex;
    const auto tile_done = [&](std::uint64_t samples) {
        const std::uint64_t done = work_done.fetch_add(samples) + samples;
        if (callbacks.progress) {
            std::unique_lock lock(progress_mutex, std::try_to_lock);
            if (lock.owns_lock()) {
                callbacks.progress(static_cast<double>(done) / total_work);
            }
        }
    };
    const auto cancelled = [&] {
        return callbacks.cancel && callbacks.cancel->load(std::memory_order_relaxed);
    };

    const auto start = std::chrono::steady_clock::now();
    const auto out_of_time = [&] {
        return callbacks.time_limit_seconds > 0 &&
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >=
                   callbacks.time_limit_seconds;
    };
    bool cancelled_mid_pass = false, stopped_after_pass = false, time_limit_reached = false;
    while (!progressive.complete()) {
        // A cancel during a pass skips its remaining tiles, even of the last pass; a stop after the
        // pass matters only if a pass is left.
        if (!progressive.next_pass(cancelled, tile_done) || cancelled()) {
            cancelled_mid_pass = true;
            break;
        }
        if (callbacks.pass_done) {
            callbacks.pass_done(film, progressive.samples_done());
        }
        if (!progressive.complete() && callbacks.stop_after_pass && callbacks.stop_after_pass->load()) {
            stopped_after_pass = true;
            break;
        }
        if (!progressive.complete() && out_of_time()) {
            time_limit_reached = true;
            break;
        }
    }
    RenderStats stats = progressive.stats();
    stats.cancelled = cancelled_mid_pass || stopped_after_pass;
    stats.time_limit_reached = time_limit_reached && !stats.cancelled;
    if (cancelled_mid_pass) {
        stats.samples_per_pixel = progressive.target_samples();  // pixels differ: what was asked for
    }
    if (callbacks.progress && !stats.cancelled && !stats.time_limit_reached) {
        callbacks.progress(1.0);
    }
    return stats;
}

}  // namespace glint
