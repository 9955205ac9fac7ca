#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "glint/core/frame.hpp"
#include "glint/core/hash.hpp"
#include "glint/core/vec.hpp"

namespace glint {
namespace {

TEST(Vec3, DotCrossAndLength) {
    const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    EXPECT_EQ(cross(x, y), z);
    EXPECT_EQ(cross(y, z), x);
    EXPECT_EQ(cross(z, x), y);
    EXPECT_DOUBLE_EQ(dot(Vec3(1, 2, 3), Vec3(4, -5, 6)), 12.0);
    EXPECT_DOUBLE_EQ(length(Vec3(3, 4, 12)), 13.0);
    EXPECT_NEAR(length(normalize(Vec3(-2, 7, 0.5))), 1.0, 1e-15);
}

TEST(Vec3, NormalizeNearUnitIsNormalizeWithinAFewUlps) {
    // Vectors whose squared length is off 1 by e, for |e| from 2^-40 to 2^-10 on both sides of the Newton
    // step's bound (2^-27), and far from unit: within 4 ulps of normalize and unit within 4 ulps, so that
    // a bound set too wide (one Newton step off by ~3e²/8) fails; beyond the bound, normalize's own bits.
    constexpr double kUlp = 0x1p-52;
    for (std::uint32_t i = 0; i < 20000; ++i) {
        const SampleKey key{5, i, 0, 0};
        const Vec3 direction =
            normalize(Vec3{key.uniform(0) - 0.5, key.uniform(1) - 0.5, key.uniform(2) - 0.5});
        const double e = std::ldexp(key.uniform(3) < 0.5 ? -1.0 : 1.0, -10 - static_cast<int>(i % 31));
        const Vec3 v = direction * std::sqrt(1 + e * (0.5 + key.uniform(4)));  // |v|² − 1 within (e/2, 3e/2)
        const Vec3 n = normalize_near_unit(v);
        const Vec3 exact = normalize(v);
        EXPECT_NEAR(length(n), 1.0, 4 * kUlp) << i;
        for (int a = 0; a < 3; ++a) {
            EXPECT_NEAR(n[a], exact[a], 4 * kUlp) << i;
        }
        if (std::abs(length_squared(v) - 1) >= 0x1p-27) {
            EXPECT_EQ(n, exact) << "beyond the bound: normalize's own result " << i;
        }
    }
    const Vec3 far = Vec3{3, -4, 12};
    EXPECT_EQ(normalize_near_unit(far), normalize(far));
}

TEST(Vec3, ReflectIsPaperEquation16) {
    // R = I − 2 (I·N) N: a ray going down at 45° bounces up at 45°.
    const Vec3 r = reflect(normalize(Vec3(1, -1, 0)), Vec3(0, 1, 0));
    EXPECT_NEAR(r.x, std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(r.y, std::sqrt(0.5), 1e-15);
    EXPECT_EQ(r.z, 0.0);
}

TEST(Frame, IsOrthonormalAndRightHandedForManyNormals) {
    for (std::uint32_t i = 0; i < 2000; ++i) {
        const SampleKey key{7, i, 0, 0};
        Vec3 n{2 * key.uniform(0) - 1, 2 * key.uniform(1) - 1, 2 * key.uniform(2) - 1};
        if (i < 6) {
            n = Vec3{};
            n[static_cast<int>(i % 3)] = i < 3 ? 1 : -1;  // the axes, where naive bases break
        }
        n = normalize(n);
        const Frame f = Frame::from_normal(n);
        EXPECT_NEAR(length(f.s), 1, 1e-12);
        EXPECT_NEAR(length(f.t), 1, 1e-12);
        EXPECT_NEAR(dot(f.s, f.t), 0, 1e-12);
        EXPECT_NEAR(dot(f.s, n), 0, 1e-12);
        EXPECT_NEAR(dot(f.t, n), 0, 1e-12);
        EXPECT_NEAR(length(cross(f.s, f.t) - n), 0, 1e-12);
        const Vec3 v{0.3, -0.5, 0.8};
        EXPECT_NEAR(length(f.to_world(f.to_local(v)) - v), 0, 1e-12);
    }
}

TEST(Hash, PermuteIsABijectionForAnyLength) {
    for (std::uint32_t length : {1u, 2u, 3u, 7u, 16u, 100u, 257u}) {
        for (std::uint32_t key : {0u, 1u, 0xdeadbeefu}) {
            std::set<std::uint32_t> seen;
            for (std::uint32_t i = 0; i < length; ++i) {
                const std::uint32_t p = permute(i, length, key);
                ASSERT_LT(p, length);
                seen.insert(p);
            }
            EXPECT_EQ(seen.size(), length);
        }
    }
}

TEST(Hash, UniformIsAPureFunctionInTheUnitInterval) {
    const SampleKey a{1, 10, 20, 3};
    const SampleKey b{1, 10, 20, 3};
    const SampleKey c{1, 11, 20, 3};
    EXPECT_EQ(a.uniform(5), b.uniform(5));
    EXPECT_NE(a.uniform(5), c.uniform(5));
    EXPECT_NE(a.uniform(5), a.uniform(6));
    double sum = 0;
    constexpr int kN = 100000;
    for (std::uint32_t i = 0; i < kN; ++i) {
        const double u = SampleKey{3, i, 0, 0}.uniform(0);
        ASSERT_GE(u, 0.0);
        ASSERT_LT(u, 1.0);
        sum += u;
    }
    // Mean of U(0,1) is 1/2 with standard deviation 1/sqrt(12 N) ≈ 0.0009: allow 5 sigma.
    EXPECT_NEAR(sum / kN, 0.5, 0.0046);
}

}  // namespace
}  // namespace glint
