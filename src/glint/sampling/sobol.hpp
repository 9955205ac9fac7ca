#pragma once

#include "glint/sampling/sampler.hpp"

namespace glint {

// Owen-scrambled Sobol sampling (beyond the paper; Burley, "Practical Hash-based Owen Scrambling",
// JCGT 2020): the first two Sobol dimensions, each Owen-scrambled by a hash with its own seed per pixel
// and 2-D dimension, and the sample index shuffled by the same kind of hash. The shuffle maps indices
// 0 … 2^k−1 onto one aligned block of 2^k Sobol points, so for n = 2^k every pixel gets a (0, k, 2)-net:
// one point in each elementary interval of area 1/n (in particular one per cell of the √n × √n grid
// when k is even, and perfect 1-D strata). Any n works and is taken as is; the guarantees are at
// powers of two. The lens (kLensDimension) is the exception: it takes Sobol's dimensions 2 and 3 of the
// film's index, so that film and lens are one 4-D Sobol point, a (3, k, 4)-net (the lens alone a
// (t, k, 2)-net with t ≤ 3, and t ≤ 2 up to 2^16 samples), stratified together instead of paired at
// random.
//
// Only the first kStratifiedDimensions 2-D dimensions are Sobol points: the film, the lens and the
// first two bounces' light and BSDF samples (or the first four bounces' BSDF samples in a scene without
// light sampling). Later dimensions are independent uniform numbers, one hash each (issue 13: a Sobol
// point costs ~130 instructions, a hash ~12). Measured with bench/peers.py's references, stratifying
// them did not pay: on RTIOW's Cornell box at 16 spp the MSE was the same within 1.3 % (its paths
// average 5 bounces, so 7 % less time per sample), on RTIOW's final scene at 32 spp 0.3 % higher; with
// only the first 4 dimensions stratified the final scene's MSE rose 5 %, with 2 twofold.
class SobolSampler final : public Sampler {
  public:
    static constexpr std::uint32_t kStratifiedDimensions = 6;
    // The render loop's PixelHashes holds these dimensions' seeds (hash.hpp).
    static_assert(PixelHashes::kDimensions == kStratifiedDimensions);

    explicit SobolSampler(std::uint32_t samples_per_pixel)
        : Sampler(kStratifiedDimensions), n_(std::max(1u, samples_per_pixel)) {}
    std::uint32_t samples_per_pixel() const override { return n_; }
    bool extendable() const override { return true; }  // the index is only scrambled, never wrapped
    Point2 sample_2d(const SampleHashes& key, std::uint32_t dimension) const override;
    // The x of sample_2d, without computing its y.
    double sample_1d(const SampleHashes& key, std::uint32_t dimension) const override;
    // The film's and the lens's points with the index they share shuffled once (the same bits as two
    // sample_2d calls; 0.9 % of the instructions of RTIOW's final scene saved).
    FilmAndLens sample_film_and_lens(const SampleHashes& key) const override;
    // The same points for eight samples at a time in AVX2 lanes, when the CPU has AVX2 and FMA: the
    // 32-bit hashes, bit reversals and table lookups of the scrambles are integer operations and the
    // conversion to double is exact, so the lanes give the same bits as one sample at a time.
    void camera_points(const PixelHashes& pixel, std::uint32_t first, bool lens,
                       std::span<FilmAndLens> out) const override;
    // The first integrator dimensions' points (all stratified: kFirstIntegratorDimension +
    // kBatchedDimensions = kStratifiedDimensions) for eight samples at a time in AVX2 lanes, by the same
    // integer operations as camera_points: when the CPU has AVX2 and FMA, else false.
    bool integrator_points(const PixelHashes& pixel, std::uint32_t first,
                           std::span<IntegratorPoints> out) const override;

  private:
    std::uint32_t n_;
};

}  // namespace glint
