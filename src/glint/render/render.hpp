// Rendering a whole image: the one tile × pass loop (progressive.hpp) run to the end on all cores, with
// progress, cancellation and statistics (architecture habit 6).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>

#include "glint/image/film.hpp"
#include "glint/integrator/integrator.hpp"
#include "glint/render/view.hpp"
#include "glint/world/world.hpp"

namespace glint {

struct RenderStats {
    double seconds = 0;
    std::uint32_t samples_per_pixel = 0;  // as taken, after the sampler's rounding
    RayCounters rays;
    // NaN or infinite radiance: counted, left out of the film, and the first one (in tile order, then
    // the order taken) named by its pixel and sample so that it can be replayed.
    std::uint64_t nonfinite_samples = 0;
    int first_nonfinite_x = -1, first_nonfinite_y = -1;
    std::uint32_t first_nonfinite_sample = 0;
    bool cancelled = false;  // stopped by `cancel` or `stop_after_pass` before all samples were taken
    // Stopped by RenderCallbacks::time_limit_seconds at the end of a pass, before all samples were
    // taken: every pixel has samples_per_pixel samples (fewer than asked for); not `cancelled`.
    bool time_limit_reached = false;

    double mrays_per_second() const { return seconds > 0 ? rays.total() / seconds * 1e-6 : 0; }
};

struct RenderCallbacks {
    // Called now and then with the fraction done in [0, 1], from one thread at a time.
    std::function<void(double fraction)> progress;
    // When set and true, the render stops at the next tile (pixels may then differ in sample count).
    const std::atomic<bool>* cancel = nullptr;
    // When set and true, the render stops at the end of the current pass, so that every pixel has the
    // same number of samples (RenderStats::samples_per_pixel): what Ctrl-C asks for.
    const std::atomic<bool>* stop_after_pass = nullptr;
    // When positive: the render stops at the end of the first pass that ends this many seconds or more
    // after it started (RenderStats::time_limit_reached), so every pixel has the same samples. With a
    // time limit the passes take samples 0–1, 2–5, 6–13, then 16 at a time (PassSizes::kGrowing), so the
    // limit is overrun by at most one pass.
    double time_limit_seconds = 0;
    // Called after each complete pass, on the calling thread, with the samples every pixel now has: the
    // film is then consistent, so this is where a checkpoint is written (render/checkpoint.hpp). When
    // set, the passes grow as with a time limit; without it or a time limit, they take 16 samples at a
    // time from the first (PassSizes::kFull), which costs less.
    std::function<void(const Film& film, std::uint32_t samples_done)> pass_done;
    // When positive: the film already holds this many samples of every pixel, from a checkpoint; the
    // render takes the rest, giving the bits of a render that never stopped.
    std::uint32_t resume_after_samples = 0;
};

// Renders view.settings.samples_per_pixel samples into every pixel of `film` (which must have the
// settings' size). The result is a pure function of the world, the view and the seed: bit-identical for
// any thread count or tile size.
RenderStats render(const World& world, const View& view, Film& film, const RenderCallbacks& callbacks = {});

// The camera ray of one sample (pixel x, y; its film and lens positions from the view's sampler), or
// nullopt where the camera sees nothing (a fisheye's corners).
std::optional<Ray> camera_ray(const View& view, const SampleHashes& key, int x, int y);
// The same from the sample's film and lens points, already drawn.
std::optional<Ray> camera_ray(const View& view, const FilmAndLens& points, int x, int y);
// The sample's points on the film and, for a camera with a lens, on the lens (else {0, 0}): what the
// view's sampler gives the key, one sample's worth of Sampler::camera_points.
FilmAndLens camera_points(const View& view, const SampleHashes& key);

// The radiance of one sample: what the render loop adds to the film for (pixel, sample index), traced
// by `integrator` (the loop's: view.integrator prepared for the world, ProgressiveRender::integrator()).
Rgb render_sample(const World& world, const View& view, const Integrator& integrator, int x, int y,
                  std::uint32_t sample, RayCounters& rays);
// The same, given the sample's key: made from SampleHashes::pixel_hash(view.settings.seed, x, y) or from
// its PixelHashes, which a loop over a pixel's samples computes once.
Rgb render_sample(const World& world, const View& view, const Integrator& integrator, int x, int y,
                  const SampleHashes& key, RayCounters& rays);
// The same, given also the key's camera points (camera_points(view, key), or the pixel's
// Sampler::camera_points, which a loop over a pixel's samples draws together).
Rgb render_sample(const World& world, const View& view, const Integrator& integrator, int x, int y,
                  const SampleHashes& key, const FilmAndLens& points, RayCounters& rays);
// One sample of a batch (render_batch): its pixel, its key and its camera points.
struct SampleJob {
    int x = 0, y = 0;
    SampleHashes key;
    FilmAndLens points;
    // The sample's first integrator dimensions, when the render loop drew them together with the pass's
    // other samples of the pixel (Sampler::integrator_points); else null.
    const IntegratorPoints* integrator_points = nullptr;
};
// Several samples at once, of one pixel or of several: out[i] is exactly what render_sample gives
// jobs[i], but the camera makes their rays together (Camera::generate_rays) and the integrator takes
// them together (Integrator::radiances). n = jobs.size() = out.size(); the render loop hands at most 16,
// whole pixels' samples of one pass (their keys made from each pixel's PixelHashes, but in a pass of one
// sample, which hashes as it goes).
void render_batch(const World& world, const View& view, const Integrator& integrator,
                  std::span<const SampleJob> jobs, RayCounters& rays, std::span<Rgb> out);

}  // namespace glint
