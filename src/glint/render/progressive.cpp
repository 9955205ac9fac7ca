#include "glint/render/progressive.hpp"

#include <tbb/blocked_range2d.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"

namespace glint {

namespace {

constexpr std::uint32_t kMaxPassSamples = 16;

// Runs `body(x0, y0, x1, y1, rays)` over the image in tiles on all cores; false if cancelled.
template <typename Body>
bool for_each_tile(int width, int height, int tile, const ProgressiveRender::CancelCheck& cancelled,
                   RayCounters& rays, const Body& body) {
    tbb::combinable<RayCounters> tile_rays;
    std::atomic<bool> stop{false};
    tbb::parallel_for(
        tbb::blocked_range2d<int>(0, height, tile, 0, width, tile), [&](const tbb::blocked_range2d<int>& r) {
            if (stop.load(std::memory_order_relaxed)) {
                return;
            }
            if (cancelled && cancelled()) {
                stop = true;
                return;
            }
            body(r.cols().begin(), r.rows().begin(), r.cols().end(), r.rows().end(), tile_rays.local());
        });
    rays += tile_rays.combine([](RayCounters a, const RayCounters& b) { return a += b; });
    return !stop.load();
}

}  // namespace

ProgressiveRender::ProgressiveRender(const Scene& scene)
    : scene_(scene),
      sampler_(make_sampler(scene.settings.sampler, scene.settings.samples_per_pixel)),
      integrator_(make_integrator(scene.settings.integrator, scene.settings)),
      film_(scene.settings.width, scene.settings.height) {
    if (!sampler_ || !integrator_) {
        throw std::invalid_argument(
            "progressive render: unknown sampler or integrator (the scene builder checks these)");
    }
    target_ = sampler_->samples_per_pixel();
}

bool ProgressiveRender::next_pass(const CancelCheck& cancelled) {
    if (complete()) {
        return true;
    }
    const std::uint32_t first = done_;
    const std::uint32_t count = std::min(next_pass_size_, target_ - done_);
    const auto start = std::chrono::steady_clock::now();
    const bool finished = for_each_tile(
        film_.width(), film_.height(), std::max(1, scene_.settings.tile_size), cancelled, rays_,
        [&](int x0, int y0, int x1, int y1, RayCounters& rays) {
            for (int y = y0; y < y1; ++y) {
                for (int x = x0; x < x1; ++x) {
                    for (std::uint32_t s = first; s < first + count; ++s) {
                        const Rgb radiance = render_sample(scene_, *sampler_, *integrator_, x, y, s, rays);
                        // Like render(): NaN and infinite samples are left out of the film.
                        if (radiance.is_finite()) {
                            film_.add_sample(x, y, radiance);
                        }
                    }
                }
            }
        });
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!finished) {
        return false;
    }
    done_ += count;
    next_pass_size_ = std::min(next_pass_size_ * 2, kMaxPassSamples);
    return true;
}

bool ProgressiveRender::coarse_preview(int block, Image& out, const CancelCheck& cancelled) {
    block = std::max(1, block);
    const int width = film_.width();
    const int height = film_.height();
    out = Image(width, height);
    const int blocks_x = (width + block - 1) / block;
    const int blocks_y = (height + block - 1) / block;
    const int grain = std::max(1, scene_.settings.tile_size / block);
    const auto start = std::chrono::steady_clock::now();
    // The "tiles" here are ranges of block indices, so that no block is shared by two tasks.
    const bool finished = for_each_tile(
        blocks_x, blocks_y, grain, cancelled, rays_, [&](int i0, int j0, int i1, int j1, RayCounters& rays) {
            for (int j = j0; j < j1; ++j) {
                for (int i = i0; i < i1; ++i) {
                    const int x0 = i * block, y0 = j * block;
                    const int x1 = std::min(x0 + block, width), y1 = std::min(y0 + block, height);
                    Rgb c =
                        render_sample(scene_, *sampler_, *integrator_, (x0 + x1) / 2, (y0 + y1) / 2, 0, rays);
                    if (!c.is_finite()) {
                        c = Rgb(0.0);
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
            }
        });
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return finished;
}

}  // namespace glint
