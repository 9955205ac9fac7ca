#include "glint/render/render.hpp"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <mutex>
#include <stdexcept>

#include "glint/scene/scene.hpp"

namespace glint {

Rgb render_sample(const Scene& scene, const Sampler& sampler, const Integrator& integrator, int x, int y,
                  std::uint32_t sample, RayCounters& rays) {
    const SampleKey key{scene.settings.seed, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y),
                        sample};
    const Point2 offset = sampler.sample_2d(key, kFilmDimension);
    const Point2 lens = sampler.sample_2d(key, kLensDimension);
    const Ray ray = scene.camera->generate_ray({x + offset.x, y + offset.y}, lens);
    if (!sees_scene(ray)) {
        return Rgb{};  // outside the camera's image (a fisheye's corners): black, nothing traced
    }
    SampleStream stream(sampler, key, kFirstIntegratorDimension);
    return integrator.radiance(scene, ray, stream, rays);
}

namespace {

struct Tile {
    int x0, y0, x1, y1;
};

std::vector<Tile> make_tiles(int width, int height, int size) {
    std::vector<Tile> tiles;
    for (int y = 0; y < height; y += size) {
        for (int x = 0; x < width; x += size) {
            tiles.push_back({x, y, std::min(x + size, width), std::min(y + size, height)});
        }
    }
    return tiles;
}

// Samples per pass: a first quick pass, then doubling, so that progress (and a preview) comes early
// and later passes amortise the per-tile overhead.
std::vector<std::uint32_t> make_passes(std::uint32_t spp) {
    std::vector<std::uint32_t> passes;
    std::uint32_t done = 0;
    std::uint32_t next = 1;
    while (done < spp) {
        const std::uint32_t n = std::min(next, spp - done);
        passes.push_back(n);
        done += n;
        next = std::min<std::uint32_t>(next * 2, 16);
    }
    return passes;
}

}  // namespace

RenderStats render(const Scene& scene, Film& film, const RenderCallbacks& callbacks) {
    const RenderSettings& settings = scene.settings;
    if (film.width() != settings.width || film.height() != settings.height) {
        throw std::invalid_argument("render: the film's size differs from the settings'");
    }
    const auto sampler = make_sampler(settings.sampler, settings.samples_per_pixel);
    const auto integrator = make_integrator(settings.integrator, settings);
    if (!sampler || !integrator) {
        throw std::invalid_argument("render: unknown sampler or integrator (the scene builder checks these)");
    }
    std::optional<tbb::global_control> thread_limit;
    if (settings.threads > 0) {
        thread_limit.emplace(tbb::global_control::max_allowed_parallelism,
                             static_cast<size_t>(settings.threads));
    }

    RenderStats stats;
    stats.samples_per_pixel = sampler->samples_per_pixel();
    const std::vector<Tile> tiles =
        make_tiles(settings.width, settings.height, std::max(1, settings.tile_size));
    const std::vector<std::uint32_t> passes = make_passes(stats.samples_per_pixel);
    const double total_work = static_cast<double>(settings.width) * settings.height * stats.samples_per_pixel;

    // Per-tile results, merged in tile order after each pass so the statistics are deterministic too.
    struct TileResult {
        RayCounters rays;
        std::uint64_t nonfinite = 0;
        int bad_x = -1, bad_y = -1;
        std::uint32_t bad_sample = 0;
    };
    std::vector<TileResult> results(tiles.size());
    std::atomic<std::uint64_t> work_done{0};
    std::mutex progress_mutex;

    const auto start = std::chrono::steady_clock::now();
    std::uint32_t first_sample = 0;
    for (const std::uint32_t pass : passes) {
        tbb::parallel_for(size_t{0}, tiles.size(), [&](size_t t) {
            if (callbacks.cancel && callbacks.cancel->load(std::memory_order_relaxed)) {
                return;
            }
            const Tile& tile = tiles[t];
            TileResult& result = results[t];
            for (int y = tile.y0; y < tile.y1; ++y) {
                for (int x = tile.x0; x < tile.x1; ++x) {
                    for (std::uint32_t s = first_sample; s < first_sample + pass; ++s) {
                        const Rgb radiance =
                            render_sample(scene, *sampler, *integrator, x, y, s, result.rays);
                        if (!radiance.is_finite()) {
                            if (result.nonfinite++ == 0) {
                                result.bad_x = x;
                                result.bad_y = y;
                                result.bad_sample = s;
                            }
                            continue;
                        }
                        film.add_sample(x, y, radiance);
                    }
                }
            }
            const auto done = work_done.fetch_add(static_cast<std::uint64_t>(tile.x1 - tile.x0) *
                                                  (tile.y1 - tile.y0) * pass) +
                              static_cast<std::uint64_t>(tile.x1 - tile.x0) * (tile.y1 - tile.y0) * pass;
            if (callbacks.progress) {
                std::unique_lock lock(progress_mutex, std::try_to_lock);
                if (lock.owns_lock()) {
                    callbacks.progress(static_cast<double>(done) / total_work);
                }
            }
        });
        first_sample += pass;
        // Read once: a cancel during this pass skipped tiles of it, even of the last pass; a stop after
        // the pass matters only if a pass is left.
        if (callbacks.cancel && callbacks.cancel->load()) {
            stats.cancelled = true;
            break;
        }
        if (first_sample < stats.samples_per_pixel && callbacks.stop_after_pass &&
            callbacks.stop_after_pass->load()) {
            stats.cancelled = true;
            stats.samples_per_pixel = first_sample;  // a whole number of passes: every pixel has these
            break;
        }
    }
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const TileResult& r : results) {
        stats.rays += r.rays;
        if (r.nonfinite && stats.nonfinite_samples == 0) {
            stats.first_nonfinite_x = r.bad_x;
            stats.first_nonfinite_y = r.bad_y;
            stats.first_nonfinite_sample = r.bad_sample;
        }
        stats.nonfinite_samples += r.nonfinite;
    }
    if (callbacks.progress && !stats.cancelled) {
        callbacks.progress(1.0);
    }
    return stats;
}

}  // namespace glint
