// Hash-based randomness. Every random number glint uses is a pure function of
// (seed, pixel, sample index, dimension): no generator state is shared between threads or carried
// between pixels, so an image is bit-identical whatever the thread count, tile size or crop.
#pragma once

#include <cstdint>

namespace glint {

// The 32 bits of x in reverse order: bit j moves to bit 31 − j.
constexpr std::uint32_t reverse_bits(std::uint32_t x) {
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
    return x;
}

// The 64 bits of x in reverse order. Reverses two 32-bit values packed in one word for the price of
// one: the low half reversed lands in the high half and the high half in the low.
constexpr std::uint64_t reverse_bits64(std::uint64_t x) {
    x = (x << 32) | (x >> 32);
    x = ((x & 0x0000ffff0000ffffull) << 16) | ((x & 0xffff0000ffff0000ull) >> 16);
    x = ((x & 0x00ff00ff00ff00ffull) << 8) | ((x & 0xff00ff00ff00ff00ull) >> 8);
    x = ((x & 0x0f0f0f0f0f0f0f0full) << 4) | ((x & 0xf0f0f0f0f0f0f0f0ull) >> 4);
    x = ((x & 0x3333333333333333ull) << 2) | ((x & 0xccccccccccccccccull) >> 2);
    x = ((x & 0x5555555555555555ull) << 1) | ((x & 0xaaaaaaaaaaaaaaaaull) >> 1);
    return x;
}

// SplitMix64's state increment, 2^64/φ: its multiples spread evenly around the 64-bit ring.
inline constexpr std::uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ull;

// One step of SplitMix64 (Steele, Lea & Flood 2014) from state x: the increment, then the finaliser, a
// bijection with full avalanche. mix64(x + k·kGoldenGamma) is the generator's output k + 1 from state x.
constexpr std::uint64_t mix64(std::uint64_t x) {
    x += kGoldenGamma;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// Hashes a sequence of integers; each is mixed in turn so that (a, b) and (b, a) differ.
constexpr std::uint64_t hash_values(std::uint64_t first) {
    return mix64(first);
}
template <typename... Rest>
constexpr std::uint64_t hash_values(std::uint64_t first, Rest... rest) {
    return mix64(first ^ hash_values(static_cast<std::uint64_t>(rest)...) * 0x2545f4914f6cdd1dull);
}

// The top 53 bits of a hash as a double in [0, 1): exact, never 1.0.
constexpr double to_unit_double(std::uint64_t bits) {
    return static_cast<double>(bits >> 11) * 0x1.0p-53;
}

// A 32-bit binary fraction as a double in [0, 1): exact, never 1.0.
constexpr double bits_to_unit(std::uint32_t bits) {
    return static_cast<double>(bits) * 0x1.0p-32;
}

// A bijection of [0, length) chosen by `key`: Kensler's hash-based permutation ("Correlated
// Multi-Jittered Sampling", Pixar 2013), with cycle walking to stay inside the range. Lets a sampler
// shuffle strata per pixel without storing any table.
constexpr std::uint32_t permute(std::uint32_t i, std::uint32_t length, std::uint32_t key) {
    std::uint32_t w = length - 1;
    w |= w >> 1;
    w |= w >> 2;
    w |= w >> 4;
    w |= w >> 8;
    w |= w >> 16;
    do {
        i ^= key;
        i *= 0xe170893du;
        i ^= key >> 16;
        i ^= (i & w) >> 4;
        i ^= key >> 8;
        i *= 0x0929eb3fu;
        i ^= key >> 23;
        i ^= (i & w) >> 1;
        i *= 1u | key >> 27;
        i *= 0x6935fa69u;
        i ^= (i & w) >> 11;
        i *= 0x74dcb303u;
        i ^= (i & w) >> 2;
        i *= 0x9e501cc3u;
        i ^= (i & w) >> 2;
        i *= 0xc860a3dfu;
        i &= w;
        i ^= i >> 5;
    } while (i >= length);
    return (i + key) % length;
}

// Where a random number is used: which pixel, which sample of that pixel. The dimension is the
// index of the number within the sample's path (film position, lens, light choice, …).
struct SampleKey {
    std::uint64_t seed = 0;
    std::uint32_t pixel_x = 0, pixel_y = 0;
    std::uint32_t sample = 0;

    std::uint64_t hash(std::uint32_t dimension) const {
        return hash_values(seed, pixel_x, pixel_y, sample, dimension);
    }
    double uniform(std::uint32_t dimension) const { return to_unit_double(hash(dimension)); }
};

// 64 random bits shared by every sample of a pixel in `dimension`, from the pixel's hash: what
// SampleHashes::pixel_bits gives and PixelHashes caches (one formula, so that the two agree to the bit).
constexpr std::uint64_t pixel_dimension_bits(std::uint64_t pixel_hash, std::uint32_t dimension) {
    return mix64(pixel_hash + dimension * kGoldenGamma);
}

// A pixel's hashes, computed by the render loop once for the samples one pass gives the pixel: the
// pixel's hash and, for its first kDimensions dimensions, SampleHashes::pixel_bits and their mix64 (the
// sobol pattern's scramble seeds). Each sample then draws its film, lens and first bounces' points
// without the two dependent mix64 a dimension cost it, at the start of its chain of dependent
// operations: bench/ab.py, 0.972 of the time for RTIOW's final scene and 0.953 for smallpt's scene at
// 16 spp, the Cornell box unchanged; the same bits. Twelve mix64 a pixel: not worth it for one sample.
struct PixelHashes {
    // sobol's stratified dimensions (SobolSampler::kStratifiedDimensions); past them the key hashes
    // afresh, as every key not made from a PixelHashes does.
    static constexpr std::uint32_t kDimensions = 6;
    explicit constexpr PixelHashes(std::uint64_t pixel_hash) : hash(pixel_hash) {
        for (std::uint32_t d = 0; d < kDimensions; ++d) {
            bits[d] = pixel_dimension_bits(pixel_hash, d);
            mixed_bits[d] = mix64(bits[d]);
        }
    }
    std::uint64_t hash;
    std::uint64_t bits[kDimensions];
    std::uint64_t mixed_bits[kDimensions];
};

// A SampleKey with its hashes computed once: the pixel's (seed, x, y) and the sample's. Every number a
// sampler draws for one dimension is then a single mix64 of one of them plus a multiple of the
// dimension, i.e. an output of a SplitMix64 stream seeded by the pixel or by the sample, instead of a
// hash of all five values afresh (issue 13: that hashing was a seventh of a render). A key made from a
// PixelHashes reads the pixel's first dimensions' bits from it instead of mixing them.
class SampleHashes {
  public:
    // Implicit, so that a sampler can be asked with a plain SampleKey (tests, tools); the renderer builds
    // one per sample and hands it down the whole path.
    constexpr SampleHashes(const SampleKey& key)
        : SampleHashes(pixel_hash(key.seed, key.pixel_x, key.pixel_y), key.sample) {}
    // From the pixel's hash, computed once for all of its samples by the render loop.
    constexpr SampleHashes(std::uint64_t pixel_hash, std::uint32_t sample)
        : pixel_(pixel_hash),
          sample_(hash_values(pixel_hash, sample)),
          sample_index_(sample),
          sample_index_reversed_(reverse_bits(sample)) {}
    // From the pixel's hashes with its cached dimensions, which the key points to: they must outlive it
    // (hence no temporary).
    constexpr SampleHashes(const PixelHashes& pixel, std::uint32_t sample)
        : SampleHashes(pixel.hash, sample) {
        pixel_cache_ = &pixel;
    }
    SampleHashes(const PixelHashes&&, std::uint32_t) = delete;
    static constexpr std::uint64_t pixel_hash(std::uint64_t seed, std::uint32_t x, std::uint32_t y) {
        return hash_values(seed, x, y);
    }

    constexpr std::uint32_t sample() const { return sample_index_; }
    // reverse_bits(sample()), kept because a low-discrepancy sampler scrambles it in (almost) every
    // dimension.
    constexpr std::uint32_t sample_reversed() const { return sample_index_reversed_; }
    // 64 random bits shared by every sample of the pixel in `dimension`: a pattern's scramble.
    constexpr std::uint64_t pixel_bits(std::uint32_t dimension) const {
        if (pixel_cache_ != nullptr && dimension < PixelHashes::kDimensions) {
            return pixel_cache_->bits[dimension];
        }
        return pixel_dimension_bits(pixel_, dimension);
    }
    // mix64(pixel_bits(dimension)): 64 more bits of the pixel's scramble in `dimension`.
    constexpr std::uint64_t pixel_bits_mixed(std::uint32_t dimension) const {
        if (pixel_cache_ != nullptr && dimension < PixelHashes::kDimensions) {
            return pixel_cache_->mixed_bits[dimension];
        }
        return mix64(pixel_bits(dimension));
    }
    // 64 random bits of this sample alone in `dimension`: a jitter, a random point.
    constexpr std::uint64_t sample_bits(std::uint32_t dimension) const {
        return mix64(sample_ + dimension * kGoldenGamma);
    }

  private:
    std::uint64_t pixel_;   // hash of (seed, pixel_x, pixel_y)
    std::uint64_t sample_;  // hash of (pixel_, sample)
    std::uint32_t sample_index_;
    std::uint32_t sample_index_reversed_;
    const PixelHashes* pixel_cache_ = nullptr;  // the render loop's, else none
};

}  // namespace glint
