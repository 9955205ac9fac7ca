// Sample patterns over the unit square (paper §II–III).
//
// A Sampler is immutable and shared by all threads. The n points a pattern places in one pixel are
// sample indices 0 … n−1 of that pixel; each point is a pure function of
// (seed, pixel, sample index, dimension), so any sample can be computed alone, in any order.
// "Dimension" numbers the independent 2-D patterns one camera path consumes: 0 is the position on the
// film, 1 the position on the lens, 2 and up are used by lights and materials. Each dimension (and each
// pixel) gets its own scramble, so patterns are not correlated across dimensions or neighbours; the one
// exception is `sobol`'s lens, stratified jointly with the film on purpose (sobol.hpp).
// Samplers are asked with SampleHashes, the key's hashes computed once per sample (a plain SampleKey
// converts), and draw each dimension's numbers from them with one or two mix64, none for the pixel's
// bits in the dimensions the render loop hashed once for the pixel (PixelHashes): the per-sample cost
// of a pattern is that and its own arithmetic. The camera points of a pass's samples are asked for
// together, from the pixel's PixelHashes (camera_points), so that a pattern can compute them side by side.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "glint/core/hash.hpp"
#include "glint/core/vec.hpp"
#include "glint/params/name_table.hpp"

namespace glint {

// The dimensions the renderer reserves before handing the stream to the integrator.
inline constexpr std::uint32_t kFilmDimension = 0;
inline constexpr std::uint32_t kLensDimension = 1;
inline constexpr std::uint32_t kFirstIntegratorDimension = 2;

// A camera sample's points on the film (kFilmDimension) and on the lens (kLensDimension).
struct FilmAndLens {
    Point2 film;
    Point2 lens;
};

// The integrator's first dimensions, which a pattern may draw for a pass's samples together
// (Sampler::integrator_points): a path's first light and BSDF samples.
inline constexpr std::uint32_t kBatchedDimensions = 4;
struct IntegratorPoints {
    Point2 point[kBatchedDimensions];  // dimension kFirstIntegratorDimension + i in point[i]
};

class Sampler {
  public:
    virtual ~Sampler() = default;

    // The number of samples per pixel this pattern takes (a pattern may round the request: jittered
    // rounds up to a square).
    virtual std::uint32_t samples_per_pixel() const = 0;

    // Point `key.sample()` of the pattern for the key's pixel in `dimension`; in [0,1)².
    virtual Point2 sample_2d(const SampleHashes& key, std::uint32_t dimension) const = 0;

    // True when a point does not depend on the number of samples the pattern was made for (the index
    // is not wrapped or permuted by it): a render may then take more samples than asked, and sample i is
    // the same whatever the target — the preview's continuous refinement.
    virtual bool extendable() const { return false; }

    // A 1-D sample; by default the x of the 2-D pattern, which is stratified into n intervals for every
    // pattern but random (regular and jittered, whose x has only √n strata, override this).
    virtual double sample_1d(const SampleHashes& key, std::uint32_t dimension) const {
        return sample_2d(key, dimension).x;
    }

    // sample_2d in the film's and the lens's dimensions, in one call: a pattern that derives both from
    // one shuffled index (sobol) computes it once.
    virtual FilmAndLens sample_film_and_lens(const SampleHashes& key) const {
        return {sample_2d(key, kFilmDimension), sample_2d(key, kLensDimension)};
    }

    // One sample's camera points: sample_film_and_lens, or with `lens` false only the film's point
    // (sample_2d in kFilmDimension; the lens is left {0, 0}).
    FilmAndLens camera_point(const SampleHashes& key, bool lens) const {
        return lens ? sample_film_and_lens(key) : FilmAndLens{sample_2d(key, kFilmDimension), {}};
    }

    // camera_point of samples first … first + out.size() − 1 of one pixel. The same bits as asking one
    // sample at a time, which is what this default does; a pattern that computes them faster together
    // (sobol, in AVX2 lanes) overrides it.
    virtual void camera_points(const PixelHashes& pixel, std::uint32_t first, bool lens,
                               std::span<FilmAndLens> out) const {
        for (std::uint32_t i = 0; i < out.size(); ++i) {
            const SampleHashes key(pixel, first + i);
            out[i] = camera_point(key, lens);
        }
    }
    // sample_2d in the kBatchedDimensions dimensions from kFirstIntegratorDimension, of samples first …
    // first + out.size() − 1 of one pixel, when the pattern computes them faster together (sobol, in AVX2
    // lanes): the same bits as asking one sample at a time, and each point's x is also sample_1d's in its
    // dimension. Returns false, and writes nothing, when the pattern has no faster way (the default):
    // the stream then asks the pattern one sample at a time.
    virtual bool integrator_points(const PixelHashes& /*pixel*/, std::uint32_t /*first*/,
                                   std::span<IntegratorPoints> /*out*/) const {
        return false;
    }

    // The first dimension from which the pattern's points are plain random ones: sample_2d(key, d) is
    // random_point(key, d) and sample_1d its x, for every d from it on. A SampleStream then draws
    // them inline, without the virtual call: most of a path's vertices are past a pattern's stratified
    // dimensions (the Cornell box: 1.8 % fewer instructions, the same bits, bench/ab.py 0.983 of the
    // time; smallpt's scene 0.977). None by default.
    std::uint32_t random_from() const { return random_from_; }

  protected:
    Sampler() = default;
    explicit Sampler(std::uint32_t random_from) : random_from_(random_from) {}

  private:
    std::uint32_t random_from_ = std::numeric_limits<std::uint32_t>::max();
};

// Two uniform numbers in [0, 1) from 64 random bits, 32 bits each: finer than any stratum needs.
constexpr Point2 unit_pair(std::uint64_t bits) {
    return {bits_to_unit(static_cast<std::uint32_t>(bits)),
            bits_to_unit(static_cast<std::uint32_t>(bits >> 32))};
}

// The random pattern's point of the key's sample in `dimension`: what every pattern past its
// random_from() gives, and what a SampleStream then draws itself.
constexpr Point2 random_point(const SampleHashes& key, std::uint32_t dimension) {
    return unit_pair(key.sample_bits(dimension));
}

// The index of the key's sample within a pattern of n points; the renderer asks only for indices below
// n, so the modulo that wraps larger ones is never paid there.
constexpr std::uint32_t pattern_index(const SampleHashes& key, std::uint32_t n) {
    return key.sample() < n ? key.sample() : key.sample() % n;
}

// The samples one camera path draws, in order: a thin cursor over (sampler, key, dimension), which
// reads the first integrator dimensions from `batched` when the render loop drew them together
// (Sampler::integrator_points; they are then the sampler's very points).
class SampleStream {
  public:
    SampleStream(const Sampler& sampler, const SampleHashes& key, std::uint32_t first_dimension,
                 const IntegratorPoints* batched = nullptr)
        : sampler_(&sampler),
          key_(key),
          dimension_(first_dimension),
          random_from_(sampler.random_from()),
          batched_(batched) {}
    Point2 next_2d() {
        const std::uint32_t dimension = dimension_++;
        if (dimension >= random_from_) {
            return random_point(key_, dimension);
        }
        if (const Point2* point = batched_point(dimension)) {
            return *point;
        }
        return sampler_->sample_2d(key_, dimension);
    }
    double next_1d() {
        const std::uint32_t dimension = dimension_++;
        if (dimension >= random_from_) {
            return random_point(key_, dimension).x;
        }
        if (const Point2* point = batched_point(dimension)) {
            return point->x;
        }
        return sampler_->sample_1d(key_, dimension);
    }

  private:
    const Point2* batched_point(std::uint32_t dimension) const {
        // Unsigned: a dimension below kFirstIntegratorDimension wraps far above kBatchedDimensions.
        const std::uint32_t i = dimension - kFirstIntegratorDimension;
        return batched_ != nullptr && i < kBatchedDimensions ? &batched_->point[i] : nullptr;
    }

    const Sampler* sampler_;
    SampleHashes key_;
    std::uint32_t dimension_;
    std::uint32_t random_from_;  // the sampler's random_from()
    const IntegratorPoints* batched_;
};

// The name → constructor table of sample patterns ("random", "jittered", …).
using SamplerFactory = std::function<std::unique_ptr<Sampler>(std::uint32_t samples_per_pixel)>;
struct SamplerEntry {
    std::string name;
    std::string summary;
    SamplerFactory create;
};
const NameTable<SamplerEntry>& sampler_table();
// nullptr when `name` is not in the table.
std::unique_ptr<Sampler> make_sampler(const std::string& name, std::uint32_t samples_per_pixel);

}  // namespace glint
