// The one render loop: tiles × passes of samples. render() runs it to the end; `glint serve` runs it a
// pass at a time, showing each, and abandons it when the scene changes.
//
// The passes take samples 0–1, 2–5, 6–13, … (then 16 at a time; a remainder of at most half a pass
// joins the last pass when both fit in 16, so 16 samples are 0–1, 2–5, 6–15), or 16 at a time from the
// start (PassSizes), of every pixel in order, so the film's sums are added in the same order whatever
// the threads, tiles or cancellations of earlier runs. Within a tile, a pass's samples are rendered in
// batches of whole pixels (render_batch). Non-finite samples (NaN, ∞) are left out of the film, counted
// and the first one named (stats()).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "glint/image/film.hpp"
#include "glint/image/image.hpp"
#include "glint/render/render.hpp"

namespace glint {

// How a render's passes are sized. Growing: 2, 4, 8, then 16 samples a pixel, for a caller that looks at
// or stops at the ends of passes (the live preview, a time limit, checkpoints): the first picture comes
// soon. Full: 16 at a time from the first pass, for a caller that wants only the finished image. A
// pixel's samples of one pass go to the sampler's lanes, the camera and the integrator together, so a
// few large passes cost less than many small ones (RTIOW's final scene at 16 spp, one pass instead of
// 2 + 4 + 10: 0.92 of the time). The images are the same bits either way.
enum class PassSizes { kGrowing, kFull };

class ProgressiveRender {
  public:
    // Returns true when the work in progress should be abandoned (checked once per tile).
    using CancelCheck = std::function<bool()>;
    // Called after each tile of a pass with the number of samples that tile took (from any thread).
    using TileDone = std::function<void(std::uint64_t samples)>;

    // `world` and `view` must outlive this object. The first form renders into a film of its own, the
    // second into `film`, which must have the view's size.
    ProgressiveRender(const World& world, const View& view, PassSizes passes = PassSizes::kGrowing);
    ProgressiveRender(const World& world, const View& view, Film& film,
                      PassSizes passes = PassSizes::kGrowing);
    ProgressiveRender(const ProgressiveRender&) = delete;
    ProgressiveRender& operator=(const ProgressiveRender&) = delete;

    // Samples per pixel once complete (the sampler's rounding of the requested count).
    std::uint32_t target_samples() const { return target_; }
    std::uint32_t samples_done() const { return done_; }
    bool complete() const { return done_ >= target_; }
    // The samples per pixel the next pass takes (0 when complete).
    std::uint32_t next_pass_samples() const;

    // Raises the target to `samples` per pixel when the view's sampler is extendable (Sampler::extendable:
    // its points do not depend on the count), so that the film then equals a render of that many
    // samples; false, changing nothing, otherwise or when `samples` is not above the target.
    bool extend_target(std::uint32_t samples);
    bool extendable() const;

    // Continues a render stopped after `samples` samples per pixel (a checkpoint's): the film must hold
    // exactly those samples of every pixel (render/checkpoint.hpp). The passes then take the samples
    // they would have taken had the render never stopped. Throws std::invalid_argument if `samples` is
    // not below the target or passes were already taken.
    void resume_after(std::uint32_t samples);

    // Takes the next pass. Returns false, leaving the film partly updated (so useless), when
    // `cancelled` said so.
    bool next_pass(const CancelCheck& cancelled = {}, const TileDone& tile_done = {});

    // A quick look before the first pass: one sample at the centre of each block × block square of
    // pixels, repeated over the square. Does not touch the film; false when cancelled. A non-finite
    // sample paints its block magenta, so that it is seen at once (the first pass then counts it).
    bool coarse_preview(int block, Image& out, const CancelCheck& cancelled = {});

    const Film& film() const { return film_; }
    // The integrator every sample is traced with: the view's, prepared for the world
    // (Integrator::prepared) once, when this object is made.
    const Integrator& integrator() const { return *integrator_; }
    // Rays, time and the non-finite samples of the passes so far; samples_per_pixel = samples_done().
    RenderStats stats() const;
    double seconds() const { return seconds_; }  // time spent in passes so far

  private:
    struct Tile {
        int x0, y0, x1, y1;
    };
    // What each tile found, merged in tile order so that the statistics are deterministic too.
    struct TileTally {
        RayCounters rays;
        std::uint64_t nonfinite = 0;
        int first_x = -1, first_y = -1;
        std::uint32_t first_sample = 0;
    };
    void plan();  // checks the view and cuts the film into tiles

    const World& world_;
    const View& view_;
    std::unique_ptr<Integrator> prepared_integrator_;  // nullptr: the view's own is used
    const Integrator* integrator_ = nullptr;
    Film own_film_;
    Film& film_;
    std::vector<Tile> tiles_;
    std::vector<TileTally> tallies_;
    RayCounters coarse_rays_;
    PassSizes pass_sizes_;
    std::uint32_t target_ = 0;
    std::uint32_t done_ = 0;
    double seconds_ = 0;
};

}  // namespace glint
