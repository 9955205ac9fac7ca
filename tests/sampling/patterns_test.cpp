// Properties every sample pattern promises (docs/scene-format.md, "Samplers"), checked on the points
// themselves: counts, range, n-rooks and jitter strata, the radical inverse values of the errata, net
// properties of the low-discrepancy patterns, purity and per-pixel variation.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "glint/core/cpu.hpp"
#include "glint/sampling/halton.hpp"
#include "glint/sampling/hammersley.hpp"
#include "glint/sampling/low_discrepancy.hpp"
#include "glint/sampling/multijittered.hpp"
#include "glint/sampling/pattern_stats.hpp"
#include "glint/sampling/sampler.hpp"
#include "glint/sampling/sobol.hpp"

namespace glint {
namespace {

const std::vector<std::string> kAllPatterns = {"regular",        "random",     "jittered", "n-rooks",
                                               "multi-jittered", "hammersley", "halton",   "sobol"};

std::vector<Point2> points_of(const std::string& name, std::uint32_t n, std::uint32_t px = 3,
                              std::uint32_t py = 5, std::uint64_t seed = 7, std::uint32_t dimension = 0) {
    const auto sampler = make_sampler(name, n);
    EXPECT_NE(sampler, nullptr) << name;
    return pattern_points(*sampler, SampleKey{seed, px, py, 0}, dimension);
}

std::uint32_t expected_count(const std::string& name, std::uint32_t requested) {
    if (name == "regular" || name == "jittered") {
        std::uint32_t k = 1;
        while (k * k < requested) {
            ++k;
        }
        return k * k;
    }
    return requested;
}

TEST(SamplerTable, HasEveryPattern) {
    for (const std::string& name : kAllPatterns) {
        EXPECT_NE(make_sampler(name, 4), nullptr) << name;
    }
    EXPECT_EQ(sampler_table().names().size(), kAllPatterns.size());
    EXPECT_EQ(make_sampler("no-such-pattern", 4), nullptr);
}

TEST(SamplePatterns, CountsAndRange) {
    for (const std::string& name : kAllPatterns) {
        for (std::uint32_t n : {1u, 2u, 7u, 8u, 16u, 30u, 64u, 100u}) {
            const auto sampler = make_sampler(name, n);
            ASSERT_EQ(sampler->samples_per_pixel(), expected_count(name, n)) << name << " n=" << n;
            for (std::uint32_t dimension : {0u, 1u, 5u}) {
                for (const Point2& p : points_of(name, n, 1, 2, 3, dimension)) {
                    ASSERT_TRUE(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1)
                        << name << " (" << p.x << ", " << p.y << ")";
                }
                SampleKey key{3, 1, 2, 0};
                for (key.sample = 0; key.sample < sampler->samples_per_pixel(); ++key.sample) {
                    const double u = sampler->sample_1d(key, dimension);
                    ASSERT_TRUE(u >= 0 && u < 1) << name;
                }
            }
        }
    }
}

TEST(SamplePatterns, OneDimensionalSamplesAreStratified) {
    // sample_1d puts one value in each of the n intervals [k/n, (k+1)/n) for every pattern that can
    // (all of them at a power-of-four count, except random).
    for (const std::string& name : kAllPatterns) {
        if (name == "random") {
            continue;
        }
        const auto sampler = make_sampler(name, 64);
        std::vector<Point2> values;
        SampleKey key{11, 4, 9, 0};
        for (key.sample = 0; key.sample < 64; ++key.sample) {
            values.push_back({sampler->sample_1d(key, 3), 0.5});
        }
        EXPECT_TRUE(points_per_cell_equal(values, 64, 1)) << name;
    }
}

TEST(SamplePatterns, NRooksConditionForNRooksAndMultiJittered) {
    for (const char* name : {"n-rooks", "multi-jittered"}) {
        for (std::uint32_t n : {1u, 5u, 8u, 16u, 17u, 64u, 256u}) {
            for (std::uint32_t px = 0; px < 3; ++px) {
                EXPECT_TRUE(satisfies_n_rooks(points_of(name, n, px, 1, 2, px))) << name << " n=" << n;
            }
        }
    }
    // The check itself fails on a pattern that breaks the condition.
    EXPECT_FALSE(satisfies_n_rooks({{0.1, 0.1}, {0.2, 0.7}}));
    EXPECT_FALSE(satisfies_n_rooks(points_of("random", 64)));
}

TEST(SamplePatterns, OnePointPerCellForJitteredAndMultiJittered) {
    for (std::uint32_t k : {1u, 2u, 4u, 5u, 16u}) {
        for (const char* name : {"jittered", "multi-jittered", "regular"}) {
            EXPECT_TRUE(points_per_cell_equal(points_of(name, k * k, 2, k), k, k)) << name << " k=" << k;
        }
    }
    // Jittered rounds 10 up to 16: one point in each cell of the 4 × 4 grid.
    EXPECT_TRUE(points_per_cell_equal(points_of("jittered", 10), 4, 4));
    // Multi-jittered takes 8 as is, on a 2 × 4 coarse grid; 7 on a 1 × 7 one.
    const MultiJitteredSampler eight(8);
    EXPECT_EQ(eight.columns(), 2u);
    EXPECT_EQ(eight.rows(), 4u);
    EXPECT_TRUE(points_per_cell_equal(points_of("multi-jittered", 8), 2, 4));
    EXPECT_EQ(MultiJitteredSampler(7).columns(), 1u);
    EXPECT_FALSE(points_per_cell_equal(points_of("random", 64), 8, 8));
}

TEST(Hammersley, RadicalInverseMatchesTheErrata) {
    const double expected[] = {0, .5, .25, .75, .125, .625, .375, .875, .0625};
    for (std::uint32_t i = 0; i < 9; ++i) {
        EXPECT_EQ(radical_inverse(2, i), expected[i]) << "Φ₂(" << i << ")";
        EXPECT_EQ(bits_to_unit(reverse_bits(i)), expected[i]);
        EXPECT_EQ(bits_to_unit(sobol_dimension0(i)), expected[i]);
    }
    EXPECT_DOUBLE_EQ(radical_inverse(3, 5), 2.0 / 3 + 1.0 / 9);  // 5 = 12₃ → 0.21₃
    EXPECT_DOUBLE_EQ(radical_inverse(3, 9), 1.0 / 27);
}

TEST(Hammersley, UnscrambledPointsAreIOverNAndPhi2) {
    const std::uint32_t n = 16;
    for (std::uint32_t i = 0; i < n; ++i) {
        const Point2 p = hammersley_point(i, n);
        EXPECT_EQ(p.x, i / 16.0);
        EXPECT_EQ(p.y, radical_inverse(2, i));
    }
    EXPECT_EQ(hammersley_point(5, 8).y, 0.625);
    EXPECT_EQ(hammersley_point(6, 8).y, 0.375);
    std::vector<Point2> plain;
    for (std::uint32_t i = 0; i < 64; ++i) {
        plain.push_back(hammersley_point(i, 64));
    }
    EXPECT_TRUE(is_base2_net(plain));
}

TEST(SamplePatterns, LowDiscrepancyPatternsAreBase2Nets) {
    // Scrambling keeps the nets: every pixel's 2^k points have one point per elementary interval.
    for (const char* name : {"hammersley", "sobol"}) {
        for (std::uint32_t n : {1u, 2u, 4u, 32u, 256u, 1024u}) {
            for (std::uint32_t px = 0; px < 3; ++px) {
                // Sobol's lens dimension is stratified jointly with the film instead (next tests).
                const std::uint32_t dimension = std::string(name) == "sobol" && px == kLensDimension ? 2 : px;
                EXPECT_TRUE(is_base2_net(points_of(name, n, px, 2 * px, 5, dimension))) << name << " n=" << n;
            }
        }
    }
    EXPECT_FALSE(is_base2_net(points_of("random", 256)));
    EXPECT_FALSE(is_base2_net(points_of("jittered", 256)));
}

TEST(SamplePatterns, SobolStratifiesOnlyItsFirstDimensions) {
    // Dimensions 0 … 5 (film, lens, the first bounces) are nets; later ones are the random pattern's
    // independent points, which with 256 points are no net.
    const auto sobol = make_sampler("sobol", 256);
    const auto random = make_sampler("random", 256);
    for (std::uint32_t dimension = 0; dimension < 12; ++dimension) {
        const SampleKey key{7, 3, 5, 0};
        const std::vector<Point2> points = pattern_points(*sobol, key, dimension);
        if (dimension == kLensDimension) {
            continue;  // Sobol's dimensions 2 and 3, a (t, m, 2)-net with t ≤ 2 for m ≤ 16 (below)
        }
        if (dimension < SobolSampler::kStratifiedDimensions) {
            EXPECT_TRUE(is_base2_net(points)) << dimension;
        } else {
            EXPECT_FALSE(is_base2_net(points)) << dimension;
            const std::vector<Point2> independent = pattern_points(*random, key, dimension);
            ASSERT_EQ(points.size(), independent.size());
            for (std::size_t i = 0; i < points.size(); ++i) {
                EXPECT_EQ(points[i].x, independent[i].x) << dimension << " " << i;
                EXPECT_EQ(points[i].y, independent[i].y) << dimension << " " << i;
                SampleKey one = key;
                one.sample = static_cast<std::uint32_t>(i);
                EXPECT_EQ(sobol->sample_1d(one, dimension), points[i].x);
            }
        }
    }
}

// Whether the points, each given as D binary fractions of 32 bits, form a (t, m, D)-net in base 2: every
// elementary box of volume 2^(t−m) (D dyadic intervals whose lengths multiply to it) holds 2^t points.
template <std::size_t D>
bool is_base2_tmd_net(const std::vector<std::array<std::uint32_t, D>>& points, std::uint32_t t) {
    std::uint32_t m = 0;
    while ((std::size_t{1} << m) < points.size()) {
        ++m;
    }
    if ((std::size_t{1} << m) != points.size() || t > m) {
        return false;
    }
    // Every way of splitting the m − t halvings among the D axes.
    std::array<std::uint32_t, D> halvings{};
    const std::function<bool(std::size_t, std::uint32_t)> boxes = [&](std::size_t axis, std::uint32_t left) {
        if (axis + 1 == D) {
            halvings[axis] = left;
            std::map<std::array<std::uint32_t, D>, std::uint32_t> counts;
            for (const auto& point : points) {
                std::array<std::uint32_t, D> box{};
                for (std::size_t a = 0; a < D; ++a) {
                    box[a] = halvings[a] == 0 ? 0 : point[a] >> (32 - halvings[a]);
                }
                ++counts[box];
            }
            for (const auto& [box, count] : counts) {
                if (count != (1u << t)) {
                    return false;
                }
            }
            return counts.size() == (std::size_t{1} << (m - t));
        }
        for (std::uint32_t h = 0; h <= left; ++h) {
            halvings[axis] = h;
            if (!boxes(axis + 1, left - h)) {
                return false;
            }
        }
        return true;
    };
    return boxes(0, m - t);
}

TEST(SamplePatterns, SobolDimensionsTwoAndThreeMatchTheirDirectionNumbers) {
    // Joe & Kuo's d = 3 and 4: x² + x + 1 with m = (1, 3), x³ + x + 1 with m = (1, 3, 1). By their
    // recurrence the third direction numbers are m₃ = 2·3 ⊕ 4·1 ⊕ 1 = 3 and m₃ = 1 given, so
    // v = (1/2, 3/4, 3/8) and (1/2, 3/4, 1/8); point i is the XOR of v_j over the set bits j of i.
    const SobolReversedTable dimension2(kSobolDimension2);
    const SobolReversedTable dimension3(kSobolDimension3);
    const double expected2[] = {0, .5, .75, .25, .375, .875, .625, .125};
    const double expected3[] = {0, .5, .75, .25, .125, .625, .875, .375};
    for (std::uint32_t i = 0; i < 8; ++i) {
        EXPECT_EQ(bits_to_unit(reverse_bits(dimension2(i))), expected2[i]) << i;
        EXPECT_EQ(bits_to_unit(reverse_bits(dimension3(i))), expected3[i]) << i;
    }
}

TEST(SamplePatterns, SobolFilmAndLensAreOneFourDimensionalNet) {
    // The film (dimension 0) and the lens (dimension 1) are Sobol's first four dimensions of the same
    // shuffled index, each Owen-scrambled: a (3, m, 4)-net in base 2 for n = 2^m (t = Σ (degree − 1) over
    // the polynomials 1, x + 1, x² + x + 1, x³ + x + 1). Film and lens drawn as two independent nets,
    // paired at random, fail this. The lens alone is a (t, m, 2)-net with t ≤ 2 up to m = 16 (t = 3 at
    // m = 17, 26 and 31, by the ranks of its generator matrices).
    for (std::uint32_t m = 0; m <= 8; ++m) {
        const auto sampler = make_sampler("sobol", 1u << m);
        for (std::uint32_t px = 0; px < 4; ++px) {
            const SampleKey key{11, px, 3 * px + 1, 0};
            const std::vector<Point2> film = pattern_points(*sampler, key, kFilmDimension);
            const std::vector<Point2> lens = pattern_points(*sampler, key, kLensDimension);
            const std::vector<Point2> bounce = pattern_points(*sampler, key, kFirstIntegratorDimension);
            std::vector<std::array<std::uint32_t, 4>> joint, unrelated;
            std::vector<std::array<std::uint32_t, 2>> lens_alone;
            const auto bits = [](double u) { return static_cast<std::uint32_t>(u * 0x1p32); };
            for (std::size_t i = 0; i < film.size(); ++i) {
                joint.push_back({bits(film[i].x), bits(film[i].y), bits(lens[i].x), bits(lens[i].y)});
                unrelated.push_back({bits(film[i].x), bits(film[i].y), bits(bounce[i].x), bits(bounce[i].y)});
                lens_alone.push_back({bits(lens[i].x), bits(lens[i].y)});
                SampleKey one = key;
                one.sample = static_cast<std::uint32_t>(i);
                EXPECT_EQ(sampler->sample_1d(one, kLensDimension), lens[i].x);
            }
            EXPECT_TRUE(is_base2_tmd_net(joint, std::min(m, 3u))) << "m=" << m << " px=" << px;
            EXPECT_TRUE(is_base2_tmd_net(lens_alone, std::min(m, 2u))) << "m=" << m << " px=" << px;
            if (m == 8) {
                EXPECT_FALSE(is_base2_tmd_net(unrelated, 3)) << px;
            }
        }
    }
}

TEST(SamplePatterns, UnscrambledSobolFirstPointsAreANet) {
    for (std::uint32_t k = 0; k <= 10; ++k) {
        std::vector<Point2> points;
        for (std::uint32_t i = 0; i < (1u << k); ++i) {
            points.push_back({bits_to_unit(sobol_dimension0(i)), bits_to_unit(sobol_dimension1(i))});
        }
        EXPECT_TRUE(is_base2_net(points)) << "k=" << k;
    }
    // The second dimension in index order: direction numbers v₁ = 1/2, v₂ = 3/4, v₃ = 5/8 (the columns
    // of Pascal's triangle mod 2), point i the XOR of v_j over the set bits j of i.
    const double expected[] = {0, .5, .75, .25, .625, .125};
    for (std::uint32_t i = 0; i < 6; ++i) {
        EXPECT_EQ(bits_to_unit(sobol_dimension1(i)), expected[i]) << i;
    }
}

TEST(SamplePatterns, SobolSecondDimensionMatchesItsDirectionNumbers) {
    // The XOR-shift form against the definition: v₁ = 1/2, v_(j+1) = v_j XOR v_j/2, point i the XOR of
    // v_j over the set bits of i. The scrambled indices the sampler feeds it use all 32 bits.
    for (std::uint32_t k = 0; k < 4096; ++k) {
        const std::uint32_t i = k < 2048 ? k : static_cast<std::uint32_t>(hash_values(k));
        std::uint32_t expected = 0, v = 1u << 31;
        for (std::uint32_t bits = i; bits != 0; bits >>= 1, v ^= v >> 1) {
            if (bits & 1u) {
                expected ^= v;
            }
        }
        ASSERT_EQ(sobol_dimension1(i), expected) << i;
        ASSERT_EQ(sobol_dimension1_reversed(i), reverse_bits(expected)) << i;
    }
}

TEST(SampleHashes, PixelBitsAreSharedByTheSamplesOfAPixelAndNothingElse) {
    // A pattern's scramble must be one per pixel and dimension: the same for every sample index.
    const SampleHashes first(SampleKey{7, 3, 4, 0}), later(SampleKey{7, 3, 4, 9});
    EXPECT_EQ(first.pixel_bits(2), later.pixel_bits(2));
    EXPECT_EQ(later.sample(), 9u);
    std::set<std::uint64_t> pixel_bits, sample_bits;
    for (const SampleKey& key : {SampleKey{7, 3, 4, 0}, SampleKey{8, 3, 4, 0}, SampleKey{7, 4, 3, 0},
                                 SampleKey{7, 3, 5, 0}, SampleKey{7, 4, 4, 0}}) {
        for (std::uint32_t dimension = 0; dimension < 4; ++dimension) {
            pixel_bits.insert(SampleHashes(key).pixel_bits(dimension));
        }
    }
    for (std::uint32_t sample = 0; sample < 4; ++sample) {
        for (std::uint32_t dimension = 0; dimension < 4; ++dimension) {
            sample_bits.insert(SampleHashes(SampleKey{7, 3, 4, sample}).sample_bits(dimension));
        }
    }
    EXPECT_EQ(pixel_bits.size(), 20u);  // seed, x, y (and swapping them) and dimension all matter
    EXPECT_EQ(sample_bits.size(), 16u);
}

TEST(SamplePatterns, RandomPointsAreUniformOverPixelsSamplesAndDimensions) {
    // 16 384 points in 16 × 16 cells: under uniformity χ² has mean 255 and standard deviation
    // √510 ≈ 22.6; 255 + 6σ is not reached by chance.
    const auto sampler = make_sampler("random", 64);
    const auto chi2_of = [&](const std::function<Point2(Point2)>& distort) {
        std::vector<int> counts(256, 0);
        for (std::uint32_t px = 0; px < 64; ++px) {
            for (std::uint32_t s = 0; s < 64; ++s) {
                const SampleHashes key(SampleKey{5, px, px / 8, s});
                for (std::uint32_t dimension = 0; dimension < 4; ++dimension) {
                    const Point2 p = distort(sampler->sample_2d(key, dimension));
                    ++counts[static_cast<size_t>(p.y * 16) * 16 + static_cast<size_t>(p.x * 16)];
                }
            }
        }
        double chi2 = 0;
        for (const int c : counts) {
            chi2 += (c - 64.0) * (c - 64.0) / 64.0;
        }
        return chi2;
    };
    const double threshold = 255 + 6 * std::sqrt(510.0);
    EXPECT_LT(chi2_of([](Point2 p) { return p; }), threshold);
    // The test sees a slight departure from uniformity: x^1.1.
    EXPECT_GT(chi2_of([](Point2 p) { return Point2{std::pow(p.x, 1.1), p.y}; }), threshold);
}

TEST(SamplePatterns, HaltonScramblesOnlyTheDigitsItsCountNeeds) {
    // Scrambling d digits and placing the rest at random keeps the point in the stratum of width 3^−d
    // that the full 21-digit scramble puts it in; different prefixes are placed independently.
    for (std::uint32_t d : {1u, 2u, 4u}) {
        const double strata = std::pow(3.0, d);
        for (std::uint32_t i = 0; i < strata; ++i) {
            const double truncated = owen_scrambled_radical_inverse3(i, 99, d);
            const double full = owen_scrambled_radical_inverse3(i, 99);
            EXPECT_EQ(std::floor(truncated * strata), std::floor(full * strata)) << "d=" << d << " i=" << i;
        }
    }
}

TEST(SamplePatterns, HaltonStratifiesInBasesTwoAndThree) {
    // The first 2^a·3^b Halton points have one point in each cell of the 2^a × 3^b grid; the Owen
    // scramble keeps it.
    for (std::uint32_t a = 0; a <= 3; ++a) {
        for (std::uint32_t b = 0; b <= 3; ++b) {
            const std::uint32_t columns = 1u << a, rows = b == 0 ? 1 : (b == 1 ? 3 : (b == 2 ? 9 : 27));
            EXPECT_TRUE(points_per_cell_equal(points_of("halton", columns * rows, a, b), columns, rows))
                << columns << "×" << rows;
        }
    }
    // Different seeds give different scrambles of Φ₃, each a permutation of the digits.
    EXPECT_NE(owen_scrambled_radical_inverse3(1, 1), owen_scrambled_radical_inverse3(1, 2));
}

TEST(SamplePatterns, PureFunctionOfSeedPixelSampleAndDimension) {
    for (const std::string& name : kAllPatterns) {
        const auto a = make_sampler(name, 16);
        const auto b = make_sampler(name, 16);
        for (std::uint32_t s : {0u, 7u, 15u}) {
            const SampleKey key{42, 10, 20, s};
            EXPECT_EQ(a->sample_2d(key, 4), b->sample_2d(key, 4)) << name;
            EXPECT_EQ(a->sample_1d(key, 4), b->sample_1d(key, 4)) << name;
            if (name != "regular" && name != "jittered") {
                // Every pattern whose x is stratified in n intervals draws its 1-D samples from it.
                EXPECT_EQ(a->sample_1d(key, 4), a->sample_2d(key, 4).x) << name;
            }
        }
        // Order of evaluation does not matter.
        EXPECT_EQ(points_of(name, 16, 1, 1, 9, 2), points_of(name, 16, 1, 1, 9, 2)) << name;
    }
}

TEST(SamplePatterns, NeighbouringPixelsAndDimensionsGetDifferentPatterns) {
    for (const std::string& name : kAllPatterns) {
        const std::vector<Point2> here = points_of(name, 16, 5, 5, 1, 0);
        const std::vector<Point2> right = points_of(name, 16, 6, 5, 1, 0);
        const std::vector<Point2> below = points_of(name, 16, 5, 6, 1, 0);
        const std::vector<Point2> lens = points_of(name, 16, 5, 5, 1, 1);
        const std::vector<Point2> reseeded = points_of(name, 16, 5, 5, 2, 0);
        auto as_set = [](const std::vector<Point2>& v) {
            std::set<std::pair<double, double>> s;
            for (const Point2& p : v)
                s.insert({p.x, p.y});
            return s;
        };
        if (name == "regular") {
            // The regular grid is the same in every pixel by definition; only the order differs.
            EXPECT_EQ(as_set(here), as_set(right));
            EXPECT_NE(here, right);
            EXPECT_NE(here, lens);
            continue;
        }
        EXPECT_NE(as_set(here), as_set(right)) << name;
        EXPECT_NE(as_set(here), as_set(below)) << name;
        EXPECT_NE(as_set(here), as_set(lens)) << name;
        EXPECT_NE(as_set(here), as_set(reseeded)) << name;
    }
}

TEST(SamplePatterns, FilmAndLensInOneCallAreTheirDimensionsPoints) {
    // The camera asks for both in one call (sobol shuffles their shared index once): the same bits as
    // asking each dimension alone, for every pattern and several counts, pixels and samples.
    for (const std::string& name : kAllPatterns) {
        for (const std::uint32_t n : {1u, 7u, 16u, 64u}) {
            const auto sampler = make_sampler(name, n);
            for (std::uint32_t px = 0; px < 5; ++px) {
                for (std::uint32_t s = 0; s < sampler->samples_per_pixel(); ++s) {
                    const SampleHashes key(SampleKey{3, px, 2 * px + 1, s});
                    const FilmAndLens both = sampler->sample_film_and_lens(key);
                    const Point2 film = sampler->sample_2d(key, kFilmDimension);
                    const Point2 lens = sampler->sample_2d(key, kLensDimension);
                    ASSERT_EQ(both.film.x, film.x) << name << " n=" << n << " px=" << px << " s=" << s;
                    ASSERT_EQ(both.film.y, film.y) << name << " n=" << n << " px=" << px << " s=" << s;
                    ASSERT_EQ(both.lens.x, lens.x) << name << " n=" << n << " px=" << px << " s=" << s;
                    ASSERT_EQ(both.lens.y, lens.y) << name << " n=" << n << " px=" << px << " s=" << s;
                }
            }
        }
    }
}

TEST(SamplePatterns, APixelsCachedHashesGiveTheSamePointsInEveryDimension) {
    // The render loop hashes each pixel's first dimensions once (PixelHashes) and hands every sample
    // a key that reads them: every pattern must draw the same bits from it as from a key that hashes
    // afresh, in the cached dimensions and past them, in 1-D and 2-D and for film and lens together.
    const std::uint32_t dimensions = PixelHashes::kDimensions + 3;
    for (const std::string& name : kAllPatterns) {
        for (const std::uint32_t n : {1u, 16u, 64u}) {
            const auto sampler = make_sampler(name, n);
            for (std::uint32_t px = 0; px < 4; ++px) {
                const PixelHashes pixel(SampleHashes::pixel_hash(11, px, 3 * px + 2));
                for (std::uint32_t s = 0; s < sampler->samples_per_pixel(); ++s) {
                    const SampleHashes fresh(SampleKey{11, px, 3 * px + 2, s});
                    const SampleHashes cached(pixel, s);
                    for (std::uint32_t d = 0; d < dimensions; ++d) {
                        ASSERT_EQ(cached.pixel_bits(d), fresh.pixel_bits(d)) << d;
                        ASSERT_EQ(cached.pixel_bits_mixed(d), mix64(fresh.pixel_bits(d))) << d;
                        const Point2 a = sampler->sample_2d(cached, d), b = sampler->sample_2d(fresh, d);
                        ASSERT_EQ(a.x, b.x) << name << " n=" << n << " s=" << s << " d=" << d;
                        ASSERT_EQ(a.y, b.y) << name << " n=" << n << " s=" << s << " d=" << d;
                        ASSERT_EQ(sampler->sample_1d(cached, d), sampler->sample_1d(fresh, d))
                            << name << " n=" << n << " s=" << s << " d=" << d;
                    }
                    const FilmAndLens a = sampler->sample_film_and_lens(cached);
                    const FilmAndLens b = sampler->sample_film_and_lens(fresh);
                    ASSERT_EQ(a.film.x, b.film.x) << name;
                    ASSERT_EQ(a.film.y, b.film.y) << name;
                    ASSERT_EQ(a.lens.x, b.lens.x) << name;
                    ASSERT_EQ(a.lens.y, b.lens.y) << name;
                }
            }
        }
    }
}

// The passes a render loop hands a pattern's batched calls, one pixel at a time: f(name, sampler, pixel,
// first, count) for every pattern, three pixels, passes that fill the eight AVX2 lanes, leave some
// empty or span several groups of eight, and first samples where the 32-bit index wraps.
void for_each_pixel_pass(const std::function<void(const std::string&, const Sampler&, const PixelHashes&,
                                                  std::uint32_t, std::uint32_t)>& f) {
    const std::vector<std::uint32_t> firsts = {0, 1, 3, 8, 1000, 0xfffffffbu};
    const std::vector<std::uint32_t> counts = {1, 2, 3, 4, 5, 8, 9, 16};
    for (const std::string& name : kAllPatterns) {
        const auto sampler = make_sampler(name, 64);
        for (std::uint32_t px = 0; px < 3; ++px) {
            const PixelHashes pixel(SampleHashes::pixel_hash(5, px, 7 * px + 1));
            for (const std::uint32_t first : firsts) {
                for (const std::uint32_t count : counts) {
                    f(name, *sampler, pixel, first, count);
                }
            }
        }
    }
}

std::string pass_name(const std::string& name, std::uint32_t first, std::uint32_t count, std::uint32_t i) {
    return name + " first=" + std::to_string(first) + " count=" + std::to_string(count) +
           " i=" + std::to_string(i);
}

TEST(SamplePatterns, CameraPointsTogetherAreOneByOnesPoints) {
    // The render loop draws the camera points of a pixel's pass in one call (sobol computes them eight
    // samples at a time in AVX2 lanes when the CPU has AVX2): the same bits as one sample at a time,
    // for every pattern, with and without a lens.
    if (!cpu_has_avx2_and_fma()) {
        GTEST_SKIP() << "no AVX2 and FMA on this CPU: every pattern answers one sample at a time, the "
                        "default this test would compare with itself";
    }
    for_each_pixel_pass([](const std::string& name, const Sampler& sampler, const PixelHashes& pixel,
                           std::uint32_t first, std::uint32_t count) {
        for (const bool lens : {true, false}) {
            std::vector<FilmAndLens> together(count);
            sampler.camera_points(pixel, first, lens, together);
            for (std::uint32_t i = 0; i < count; ++i) {
                const SampleHashes key(pixel, first + i);
                const FilmAndLens alone = lens ? sampler.sample_film_and_lens(key)
                                               : FilmAndLens{sampler.sample_2d(key, kFilmDimension), {}};
                const std::string where = pass_name(name, first, count, i) + " lens=" + std::to_string(lens);
                ASSERT_EQ(together[i].film, alone.film) << where;
                ASSERT_EQ(together[i].lens, alone.lens) << where;
            }
        }
    });
}

TEST(SamplePatterns, IntegratorPointsTogetherAreOneByOnesPoints) {
    // The render loop asks for a pixel's pass's first integrator dimensions in one call; a pattern that
    // answers (sobol, in AVX2 lanes) must give each sample's sample_2d in each of those dimensions, and
    // sample_1d as the x, to the bit.
    std::set<std::string> answered;
    for_each_pixel_pass([&](const std::string& name, const Sampler& sampler, const PixelHashes& pixel,
                            std::uint32_t first, std::uint32_t count) {
        std::vector<IntegratorPoints> together(count);
        if (!sampler.integrator_points(pixel, first, together)) {
            return;
        }
        answered.insert(name);
        for (std::uint32_t i = 0; i < count; ++i) {
            const SampleHashes key(pixel, first + i);
            for (std::uint32_t d = 0; d < kBatchedDimensions; ++d) {
                const std::uint32_t dimension = kFirstIntegratorDimension + d;
                const std::string where = pass_name(name, first, count, i) + " d=" + std::to_string(d);
                ASSERT_EQ(together[i].point[d], sampler.sample_2d(key, dimension)) << where;
                ASSERT_EQ(together[i].point[d].x, sampler.sample_1d(key, dimension)) << where;
            }
        }
    });
    // Not a test of nothing: with AVX2, sobol answers (without, every pattern declines, and the stream
    // asks one sample at a time).
    if (cpu_has_avx2_and_fma()) {
        EXPECT_EQ(answered, std::set<std::string>{"sobol"});
    } else {
        EXPECT_TRUE(answered.empty());
    }
}

TEST(SamplePatterns, AStreamReadsTheBatchedDimensionsAndAsksForTheOthers) {
    // Points no pattern would give, so that the test sees where each number came from.
    IntegratorPoints batched;
    for (std::uint32_t d = 0; d < kBatchedDimensions; ++d) {
        batched.point[d] = {2.0 + d, -1.0 - d};
    }
    const auto sampler = make_sampler("sobol", 16);
    const SampleHashes key(SampleKey{3, 4, 5, 6});
    // From dimension 0: the camera's two from the pattern, then the batch's, then the pattern again.
    SampleStream stream(*sampler, key, 0, &batched);
    EXPECT_EQ(stream.next_2d(), sampler->sample_2d(key, 0));
    EXPECT_EQ(stream.next_1d(), sampler->sample_1d(key, 1));
    EXPECT_EQ(stream.next_2d(), batched.point[0]);
    EXPECT_EQ(stream.next_1d(), batched.point[1].x);
    EXPECT_EQ(stream.next_2d(), batched.point[2]);
    EXPECT_EQ(stream.next_2d(), batched.point[3]);
    EXPECT_EQ(stream.next_2d(), sampler->sample_2d(key, kFirstIntegratorDimension + kBatchedDimensions));
    EXPECT_EQ(stream.next_1d(), sampler->sample_1d(key, kFirstIntegratorDimension + kBatchedDimensions + 1));
    // Without a batch, every number from the pattern.
    SampleStream alone(*sampler, key, kFirstIntegratorDimension);
    for (std::uint32_t d = 0; d < kBatchedDimensions + 2; ++d) {
        EXPECT_EQ(alone.next_2d(), sampler->sample_2d(key, kFirstIntegratorDimension + d));
    }
}

TEST(SamplePatterns, AStreamDrawsThePatternsRandomDimensionsAsThePatternDoes) {
    // A stream draws a pattern's points from random_from() on itself, without asking the pattern: they
    // must be the pattern's own, in every pattern, in 1-D and 2-D, for samples below and above the count.
    std::set<std::string> declaring;
    for (const std::string& name : kAllPatterns) {
        SCOPED_TRACE(name);
        const auto sampler = make_sampler(name, 16);
        const std::uint32_t from = sampler->random_from();
        if (from == std::numeric_limits<std::uint32_t>::max()) {
            continue;
        }
        declaring.insert(name);
        for (const std::uint32_t sample : {0u, 5u, 15u, 40u}) {
            const SampleHashes key(SampleKey{7, 11, 13, sample});
            const std::uint32_t first = std::max(from, kFirstIntegratorDimension);
            SampleStream stream(*sampler, key, first);
            for (std::uint32_t d = first; d < first + 12; d += 2) {
                EXPECT_EQ(stream.next_2d(), sampler->sample_2d(key, d));
                EXPECT_EQ(stream.next_1d(), sampler->sample_1d(key, d + 1));
            }
        }
    }
    // Not a test of nothing: the two patterns that declare it.
    EXPECT_EQ(declaring, (std::set<std::string>{"random", "sobol"}));
    EXPECT_EQ(make_sampler("sobol", 16)->random_from(), SobolSampler::kStratifiedDimensions);
}

TEST(SamplePatterns, FilmAndLensDimensionsAreUncorrelated) {
    // Over many pixels, the film x and lens x of one sample must not be correlated (a pattern reusing
    // the same index order in both dimensions would give a correlation near 1).
    for (const std::string& name : kAllPatterns) {
        const auto sampler = make_sampler(name, 16);
        double sum_xy = 0, sum_x = 0, sum_y = 0, sum_xx = 0, sum_yy = 0;
        int count = 0;
        for (std::uint32_t px = 0; px < 32; ++px) {
            for (std::uint32_t s = 0; s < 16; ++s) {
                const SampleKey key{1, px, 0, s};
                const double a = sampler->sample_2d(key, kFilmDimension).x;
                const double b = sampler->sample_2d(key, kLensDimension).x;
                sum_x += a, sum_y += b, sum_xy += a * b, sum_xx += a * a, sum_yy += b * b, ++count;
            }
        }
        const double cov = sum_xy / count - sum_x / count * sum_y / count;
        const double corr = cov / std::sqrt((sum_xx / count - sum_x * sum_x / count / count) *
                                            (sum_yy / count - sum_y * sum_y / count / count));
        EXPECT_LT(std::abs(corr), 0.15) << name;  // 512 pairs: the standard error is about 0.044
    }
}

TEST(PatternStats, DiscrepancyOfOnePointMatchesClosedForms) {
    // One point (x, y): D∞* = max(x, y, 1 − xy); T² = 1/9 − (1−x²)(1−y²)/2 + (1−x)(1−y).
    for (const Point2 p : {Point2{0.5, 0.5}, Point2{0.2, 0.7}, Point2{0.9, 0.1}}) {
        EXPECT_NEAR(star_discrepancy_linf({p}), std::max({p.x, p.y, 1 - p.x * p.y}), 1e-15);
        const double t2 = 1.0 / 9 - (1 - p.x * p.x) * (1 - p.y * p.y) / 2 + (1 - p.x) * (1 - p.y);
        EXPECT_NEAR(star_discrepancy_l2({p}), std::sqrt(t2), 1e-15);
    }
}

TEST(PatternStats, DiscrepancyOrdersPatterns) {
    // Averaged over pixels, a 256-point Sobol or Hammersley set has far lower discrepancy than random.
    double random = 0, sobol = 0, hammersley = 0;
    for (std::uint32_t px = 0; px < 8; ++px) {
        random += star_discrepancy_linf(points_of("random", 256, px));
        sobol += star_discrepancy_linf(points_of("sobol", 256, px));
        hammersley += star_discrepancy_l2(points_of("hammersley", 256, px));
    }
    EXPECT_LT(sobol, 0.5 * random);
    EXPECT_GT(random / 8, 0.03);  // ≈ 1.2/√256 for random points
    EXPECT_LT(hammersley / 8, 0.01);
}

TEST(PatternStats, MinimumDistance) {
    EXPECT_DOUBLE_EQ(minimum_distance({{0.1, 0.1}, {0.9, 0.9}, {0.4, 0.5}}), 0.5);
    // The regular 8 × 8 grid: its spacing.
    EXPECT_NEAR(minimum_distance(points_of("regular", 64)), 1.0 / 8, 1e-12);
}

}  // namespace
}  // namespace glint
