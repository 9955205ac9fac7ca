// Rendering a pass at a time, for previews that refine while the user watches (`glint serve`).
//
// The passes take samples 0, 1, 2–3, 4–7, … of every pixel in order, so once all are taken the film
// holds exactly what render() would have produced: same sums in the same order, bit for bit.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "glint/image/film.hpp"
#include "glint/image/image.hpp"
#include "glint/integrator/integrator.hpp"
#include "glint/sampling/sampler.hpp"

namespace glint {

struct Scene;

class ProgressiveRender {
  public:
    // Returns true when the work in progress should be abandoned (checked once per tile).
    using CancelCheck = std::function<bool()>;

    // `scene` must outlive this object. Throws std::invalid_argument on an unknown sampler or integrator.
    explicit ProgressiveRender(const Scene& scene);

    // Samples per pixel once complete (the sampler's rounding of the requested count).
    std::uint32_t target_samples() const { return target_; }
    std::uint32_t samples_done() const { return done_; }
    bool complete() const { return done_ >= target_; }

    // Takes the next pass: the first is one sample, each later one doubles, up to 16 samples.
    // Returns false, leaving the film partly updated (so useless), when `cancelled` said so.
    bool next_pass(const CancelCheck& cancelled = {});

    // A quick look before the first pass: one sample at the centre of each block × block square of
    // pixels, repeated over the square. Does not touch the film; false when cancelled.
    bool coarse_preview(int block, Image& out, const CancelCheck& cancelled = {});

    const Film& film() const { return film_; }
    RayCounters rays() const { return rays_; }
    double seconds() const { return seconds_; }  // time spent in passes so far
    double mrays_per_second() const { return seconds_ > 0 ? rays_.total() / seconds_ * 1e-6 : 0; }

  private:
    const Scene& scene_;
    std::unique_ptr<Sampler> sampler_;
    std::unique_ptr<Integrator> integrator_;
    Film film_;
    std::uint32_t target_ = 0;
    std::uint32_t done_ = 0;
    std::uint32_t next_pass_size_ = 1;
    RayCounters rays_;
    double seconds_ = 0;
};

}  // namespace glint
