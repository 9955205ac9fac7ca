#include "glint/render/progressive.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <span>
#include <stdexcept>

#include "glint/core/fixed_vector.hpp"

namespace glint {

namespace {

// Passes grow 2, 4, 8, then stay at 16 samples (PassSizes::kGrowing): the first picture comes soon, and
// later passes amortise the per-tile overhead. A small remainder joins the last pass (see
// next_pass_samples). PassSizes::kFull takes 16 at a time from the start.
constexpr std::uint32_t kMaxPassSamples = 16;
// The first pass takes two samples a pixel, not one: a pass of two draws its samples' camera and
// integrator points together (sobol: in AVX2 lanes) and hashes each pixel once, where a pass of one
// draws each sample's alone. Two samples a pixel cost less than twice one (bench/ab.py, CPU time): the
// Cornell box at 3 spp, one pass where it was 1 + 2, took 0.93 of the time on one thread and 0.91 on
// two; at 2 spp, one pass where it was 1 + 1, 0.96 on one thread; RTIOW's final scene and smallpt's
// at 7 to 32 spp within noise. The live preview shows its coarse picture (coarse_preview) before the
// first pass, so a pass of one sample is not what makes it quick.
constexpr std::uint32_t kFirstPassSamples = 2;

// Runs `body(index)` for every index in [0, count) on all cores; false if `cancelled` said so first.
template <typename Body>
bool parallel_tiles(std::size_t count, const ProgressiveRender::CancelCheck& cancelled, const Body& body) {
    std::atomic<bool> stop{false};
    tbb::parallel_for(std::size_t{0}, count, [&](std::size_t i) {
        if (stop.load(std::memory_order_relaxed)) {
            return;
        }
        if (cancelled && cancelled()) {
            stop = true;
            return;
        }
        body(i);
    });
    return !stop.load();
}

}  // namespace

ProgressiveRender::ProgressiveRender(const World& world, const View& view, PassSizes passes)
    : world_(world),
      view_(view),
      own_film_(view.settings.width, view.settings.height),
      film_(own_film_),
      pass_sizes_(passes) {
    plan();
}

ProgressiveRender::ProgressiveRender(const World& world, const View& view, Film& film, PassSizes passes)
    : world_(world), view_(view), own_film_(0, 0), film_(film), pass_sizes_(passes) {
    if (film.width() != view.settings.width || film.height() != view.settings.height) {
        throw std::invalid_argument("render: the film's size differs from the settings'");
    }
    plan();
}

void ProgressiveRender::plan() {
    if (!view_.camera || !view_.sampler || !view_.integrator) {
        throw std::invalid_argument("render: the view has no camera, sampler or integrator");
    }
    prepared_integrator_ =
        view_.integrator->prepared(world_, *view_.camera, {view_.settings.width, view_.settings.height});
    integrator_ = prepared_integrator_ ? prepared_integrator_.get() : view_.integrator.get();
    target_ = view_.sampler->samples_per_pixel();
    const int size = std::max(1, view_.settings.tile_size);
    const PixelWindow window = view_.settings.rendered_window();  // the film has the settings' size
    for (int y = window.y0; y < window.y1; y += size) {
        for (int x = window.x0; x < window.x1; x += size) {
            tiles_.push_back({x, y, std::min(x + size, window.x1), std::min(y + size, window.y1)});
        }
    }
    tallies_.resize(tiles_.size());
}

bool ProgressiveRender::extendable() const {
    return view_.sampler->extendable();
}

bool ProgressiveRender::extend_target(std::uint32_t samples) {
    if (!extendable() || samples <= target_) {
        return false;
    }
    target_ = samples;
    return true;
}

void ProgressiveRender::resume_after(std::uint32_t samples) {
    if (done_ != 0 || samples >= target_) {
        throw std::invalid_argument("render: a render resumes only before its first pass, below its target");
    }
    done_ = samples;
}

std::uint32_t ProgressiveRender::next_pass_samples() const {
    const std::uint32_t remaining = target_ - std::min(done_, target_);
    if (pass_sizes_ == PassSizes::kFull) {
        return std::min(remaining, kMaxPassSamples);
    }
    const std::uint32_t growing = std::min(done_ + kFirstPassSamples, kMaxPassSamples);
    if (remaining <= growing) {
        return remaining;
    }
    // The growing passes add up to 2^k - 2, so a power-of-two target, the usual one, would end in a
    // pass of two samples: a whole pass over the image for them. A remainder of at most half a pass is
    // taken with this pass when both fit in one: 3 samples are one pass, 8 are 2 + 6, 16 are 2 + 4 + 10
    // (32 are 2 + 4 + 8 + 16 + 2). (When it was made, the passes began with one sample and a
    // one-sample pass took its samples one at a time; the merge gave RTIOW at 4 spp 0.946 of the time.
    // Once such a pass was batched across pixels, it measured within noise: RTIOW at 16 spp took 0.987
    // (0.955–1.046) of the time without it.) (Splitting a larger remainder evenly, 32 samples as
    // 1 + 2 + 4 + 8 + 8 + 9, cost a pass's per-pixel set-up more than the small last pass of
    // 1 + 2 + 4 + 8 + 16 + 1 cost: 1.019 of RTIOW's time.)
    if (remaining <= kMaxPassSamples && 2 * (remaining - growing) <= growing) {
        return remaining;
    }
    return growing;
}

bool ProgressiveRender::next_pass(const CancelCheck& cancelled, const TileDone& tile_done) {
    if (complete()) {
        return true;
    }
    const std::uint32_t first = done_;
    const std::uint32_t count = next_pass_samples();
    const auto start = std::chrono::steady_clock::now();
    const bool finished = parallel_tiles(tiles_.size(), cancelled, [&](std::size_t t) {
        const Tile& tile = tiles_[t];
        TileTally& tally = tallies_[t];
        // The pass's samples go to the camera and the integrator in batches of whole pixels, up to
        // kMaxPassSamples samples: one pixel's in a pass of 9 to 16 samples, 16 pixels' in a pass of one.
        // Batched, a sample costs less (the camera's and the sampler's lanes full, the batch's camera rays
        // traced one after the other through the same part of the tree): before, a pass of one sample a
        // pixel took its samples one at a time and a pass of two took them in pairs, and on RTIOW's final
        // scene each of their samples cost 1.2–1.3 times one of a pass of 16.
        FixedVector<SampleJob, kMaxPassSamples> jobs;
        // The batch's pixels' hashes, to which its keys refer: only in a pass of two or more samples a
        // pixel, so a batch has at most kMaxPassSamples / 2 of them.
        FixedVector<PixelHashes, kMaxPassSamples / 2> pixels;
        // The batch's samples' first integrator dimensions, when the sampler draws them together (sobol),
        // to which the jobs point: like the hashes, only in a pass of two or more samples a pixel.
        FixedVector<IntegratorPoints, kMaxPassSamples> integrator_points;
        const auto render_jobs = [&] {
            FixedVector<Rgb, kMaxPassSamples> radiances;
            for (std::size_t i = 0; i < jobs.size(); ++i) {
                radiances.emplace_back();
            }
            render_batch(world_, view_, *integrator_, jobs.span(), tally.rays, radiances.span());
            // In the batch's order: each pixel's samples in order, as the film must add them.
            for (std::size_t i = 0; i < jobs.size(); ++i) {
                const SampleJob& job = jobs[i];
                const Rgb& radiance = radiances[i];
                if (!radiance.is_finite()) {
                    if (tally.nonfinite++ == 0) {
                        tally.first_x = job.x;
                        tally.first_y = job.y;
                        tally.first_sample = job.key.sample();
                    }
                    continue;
                }
                film_.add_sample(job.x, job.y, radiance);
            }
            jobs.clear();
            pixels.clear();
            integrator_points.clear();
        };
        const bool lens = view_.camera->uses_lens();
        for (int y = tile.y0; y < tile.y1; ++y) {
            for (int x = tile.x0; x < tile.x1; ++x) {
                if (jobs.size() + count > kMaxPassSamples) {
                    render_jobs();
                }
                const std::uint64_t pixel_hash = SampleHashes::pixel_hash(
                    view_.settings.seed, static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y));
                if (count > 1) {
                    // The pixel's hashed dimensions, computed once for its samples (they cost two samples'
                    // worth of hashing), and its samples' camera points drawn together (sobol: eight at a
                    // time in AVX2 lanes; RTIOW's final scene at 32 spp rendered in 0.96–0.97 of the time).
                    const PixelHashes& pixel = pixels.emplace_back(pixel_hash);
                    std::array<FilmAndLens, kMaxPassSamples> points;
                    view_.sampler->camera_points(pixel, first, lens, std::span(points.data(), count));
                    // The paths' first light and BSDF samples too (sobol: eight at a time in AVX2 lanes).
                    const std::size_t batched = integrator_points.size();
                    for (std::uint32_t i = 0; i < count; ++i) {
                        integrator_points.emplace_back();
                    }
                    const bool drawn = view_.sampler->integrator_points(
                        pixel, first, integrator_points.span().subspan(batched, count));
                    for (std::uint32_t i = 0; i < count; ++i) {
                        jobs.emplace_back(SampleJob{x, y, SampleHashes(pixel, first + i), points[i],
                                                    drawn ? &integrator_points[batched + i] : nullptr});
                    }
                } else {
                    // A one-sample pass hashes as it goes: the same bits.
                    const SampleHashes key(pixel_hash, first);
                    jobs.emplace_back(SampleJob{x, y, key, camera_points(view_, key)});
                }
            }
        }
        render_jobs();
        if (tile_done) {
            tile_done(static_cast<std::uint64_t>(tile.x1 - tile.x0) * (tile.y1 - tile.y0) * count);
        }
    });
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!finished) {
        return false;
    }
    done_ += count;
    return true;
}

RenderStats ProgressiveRender::stats() const {
    RenderStats stats;
    stats.seconds = seconds_;
    stats.samples_per_pixel = done_;
    stats.rays = coarse_rays_;
    for (const TileTally& tally : tallies_) {
        stats.rays += tally.rays;
        if (tally.nonfinite && stats.nonfinite_samples == 0) {
            stats.first_nonfinite_x = tally.first_x;
            stats.first_nonfinite_y = tally.first_y;
            stats.first_nonfinite_sample = tally.first_sample;
        }
        stats.nonfinite_samples += tally.nonfinite;
    }
    return stats;
}

bool ProgressiveRender::coarse_preview(int block, Image& out, const CancelCheck& cancelled) {
    block = std::max(1, block);
    const int width = film_.width();
    const int height = film_.height();
    out = Image(width, height);
    const int blocks_x = (width + block - 1) / block;
    const int blocks_y = (height + block - 1) / block;
    std::vector<RayCounters> row_rays(static_cast<std::size_t>(blocks_y));
    const auto start = std::chrono::steady_clock::now();
    // A task per row of blocks, so that no block is shared by two tasks.
    const bool finished = parallel_tiles(static_cast<std::size_t>(blocks_y), cancelled, [&](std::size_t j) {
        for (int i = 0; i < blocks_x; ++i) {
            const int x0 = i * block, y0 = static_cast<int>(j) * block;
            const int x1 = std::min(x0 + block, width), y1 = std::min(y0 + block, height);
            Rgb c = render_sample(world_, view_, *integrator_, (x0 + x1) / 2, (y0 + y1) / 2, 0, row_rays[j]);
            if (!c.is_finite()) {
                c = Rgb(1.0, 0.0, 1.0);
            }
            for (int y = y0; y < y1; ++y) {
                for (int x = x0; x < x1; ++x) {
                    float* p = out.pixel(x, y);
                    p[0] = static_cast<float>(c.r);
                    p[1] = static_cast<float>(c.g);
                    p[2] = static_cast<float>(c.b);
                }
            }
        }
    });
    for (const RayCounters& r : row_rays) {
        coarse_rays_ += r;
    }
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return finished;
}

}  // namespace glint
