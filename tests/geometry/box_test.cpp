#include <gtest/gtest.h>

#include "geometry/shape_testing.hpp"
#include "glint/geometry/box.hpp"

namespace glint {
namespace {

using testing::check_area_samples;
using testing::check_random_hits;
using testing::check_scale_independence;
using testing::scene_error;

// Signed distance to the box [lo, hi]'s surface (negative inside).
double box_distance(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    const Vec3 c = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    const Vec3 q = abs(p - c) - half;
    const Vec3 outside = max(q, Vec3{});
    return length(outside) + std::min(max_component(q), 0.0);
}

// The outward normal of the face nearest to p.
Vec3 box_normal(const Vec3& p, const Vec3& lo, const Vec3& hi) {
    const Vec3 c = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    int axis = 0;
    double best = kInf;
    for (int i = 0; i < 3; ++i) {
        const double gap = std::abs(std::abs(p[i] - c[i]) - half[i]);
        if (gap < best) {
            best = gap;
            axis = i;
        }
    }
    Vec3 n;
    n[axis] = p[axis] > c[axis] ? 1 : -1;
    return n;
}

const Vec3 kLo{-1, -2, -3}, kHi{1, 2, 3};

TEST(Box, HitsFromOutsideAndInsideWithOutwardNormals) {
    const Box box(kLo, kHi);
    Hit hit;
    ASSERT_TRUE(box.intersect({{-5, 0.5, 0.5}, {1, 0, 0}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 4);
    EXPECT_EQ(hit.point, Vec3(-1, 0.5, 0.5));
    EXPECT_EQ(hit.normal, Vec3(-1, 0, 0));
    EXPECT_DOUBLE_EQ(hit.uv.x, 2.5 / 4);
    EXPECT_DOUBLE_EQ(hit.uv.y, 3.5 / 6);
    ASSERT_TRUE(box.intersect({{0, 0, 0}, {0, 0.5, 0}}, kInf, hit));  // from inside: the face it leaves by
    EXPECT_DOUBLE_EQ(hit.t, 4);
    EXPECT_EQ(hit.normal, Vec3(0, 1, 0));
    ASSERT_TRUE(box.intersect({{0.5, 0.5, 10}, {0, 0, -1}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 7);
    EXPECT_EQ(hit.normal, Vec3(0, 0, 1));
    EXPECT_FALSE(box.intersect({{0, 5, 0}, {0, 1, 0}}, kInf, hit));  // behind
    EXPECT_FALSE(box.intersect({{-5, 0, 0}, {1, 0, 0}}, 4, hit));    // t_max
    EXPECT_TRUE(box.intersect({{-5, 0, 0}, {1, 0, 0}}, 4.000001, hit));
    EXPECT_FALSE(box.intersect({{-5, 2.000001, 0}, {1, 0, 0}}, kInf, hit));  // grazing, just outside a face
    EXPECT_FALSE(box.intersect({{-5, 0, 0}, {1, 1, 0}}, kInf, hit));         // passes beside a corner
    EXPECT_FALSE(box.occluded({{-5, 0, 0}, {1, 1, 0}}, kInf));
    EXPECT_TRUE(box.occluded({{-5, 0, 0}, {1, 0, 0}}, 4.5));
    EXPECT_FALSE(box.occluded({{-5, 0, 0}, {1, 0, 0}}, 3.5));
}

// The slab test as it was written first: the two t's of each axis divided out and swapped into order,
// and a ray along a slab tested apart (inside it: no limit; outside: a miss). The box's t, axis and
// side must equal it bit for bit.
double reference_slab_t(const Vec3& lo, const Vec3& hi, const Ray& ray, double t_max, int& axis, int& side) {
    double t_enter = -kInf, t_exit = kInf;
    int enter_axis = -1, exit_axis = -1;
    for (int i = 0; i < 3; ++i) {
        const double o = ray.origin[i];
        const double d = ray.direction[i];
        if (d == 0) {
            if (o < lo[i] || o > hi[i]) {
                return kInf;
            }
            continue;
        }
        double t0 = (lo[i] - o) / d;
        double t1 = (hi[i] - o) / d;
        if (t0 > t1) {
            std::swap(t0, t1);
        }
        if (t0 > t_enter) {
            t_enter = t0;
            enter_axis = i;
        }
        if (t1 < t_exit) {
            t_exit = t1;
            exit_axis = i;
        }
    }
    if (t_enter > t_exit) {
        return kInf;
    }
    const bool entering = t_enter > 0;
    const double t = entering ? t_enter : t_exit;
    axis = entering ? enter_axis : exit_axis;
    if (!(t > 0) || t >= t_max || axis < 0) {
        return kInf;
    }
    side = (ray.direction[axis] > 0) == entering ? -1 : 1;
    return t;
}

TEST(Box, SlabTestGivesTheReferenceHitsBitForBit) {
    const Box box(kLo, kHi);
    const Bounds3 around{2 * kLo, 2 * kHi};
    int hits = 0, along_planes = 0, hits_along_planes = 0;
    for (std::uint32_t i = 0; i < 200000; ++i) {
        Ray ray{testing::random_point_in(around, 7, i), testing::random_direction(7, i)};
        // Every other ray runs along one or two slabs (direction ±0 there), a quarter of those starting
        // on a slab's plane, some on a face, some on an edge; some rays start on a face across its slab.
        const auto pick = [&](std::uint32_t dimension) {
            return static_cast<int>(testing::uniform(7, i, dimension) * 3);
        };
        if (i % 2 == 1) {
            const int a = pick(5);
            ray.direction[a] = i % 4 == 1 ? 0.0 : -0.0;
            if (i % 8 == 3) {
                ray.direction[(a + 1) % 3] = 0.0;
            }
            if (i % 16 < 4) {
                ray.origin[a] = i % 32 < 16 ? kLo[a] : kHi[a];
                if (i % 64 < 8) {
                    ray.origin[(a + 2) % 3] = kHi[(a + 2) % 3];
                }
                ++along_planes;
            }
        } else if (i % 16 == 2) {
            const int a = pick(5);
            ray.origin[a] = i % 32 < 16 ? kLo[a] : kHi[a];
        }
        const double t_max = i % 3 == 0 ? kInf : 4 * testing::uniform(7, i, 6);
        int axis = -1, side = 0;
        const double t = reference_slab_t(kLo, kHi, ray, t_max, axis, side);
        Hit hit;
        const bool found = box.intersect(ray, t_max, hit);
        ASSERT_EQ(found, t != kInf) << i;
        ASSERT_EQ(box.occluded(ray, t_max), found) << i;
        if (found) {
            ++hits;
            hits_along_planes += i % 2 == 1 && i % 16 < 4;
            Vec3 normal;
            normal[axis] = side;
            ASSERT_EQ(hit.t, t) << i;
            ASSERT_EQ(hit.normal, normal) << i;
        }
    }
    EXPECT_GT(hits, 30000);
    EXPECT_GT(along_planes, 20000);
    EXPECT_GT(hits_along_planes, 2000);
}

TEST(Box, RandomHitsLieOnTheSurfaceWithOutwardNormals) {
    const Box box(kLo, kHi);
    check_random_hits(
        box, [](const Vec3& p) { return box_distance(p, kLo, kHi); },
        [](const Vec3& p) { return box_normal(p, kLo, kHi); });
}

TEST(Box, AreaSamplesAreUniformOverTheFaces) {
    const Box box(kLo, kHi);
    EXPECT_DOUBLE_EQ(box.area(), 2 * (2 * 4 + 4 * 6 + 6 * 2));
    const auto distance = [](const Vec3& p) { return box_distance(p, kLo, kHi); };
    const Vec3 mean = check_area_samples(box, 400, distance, 6);
    EXPECT_NEAR(length(mean), 0, 5e-3);  // the grid quantises the faces' shares to 1/400
    // Each face gets its share of the area: count the samples on the +z face (area 8 of 88).
    int on_top = 0;
    for (int i = 0; i < 100; ++i) {
        for (int j = 0; j < 100; ++j) {
            const ShapeSample s = *box.sample_area({(i + 0.5) / 100, (j + 0.5) / 100});
            EXPECT_EQ(s.normal, box_normal(s.point, kLo, kHi)) << s.point;
            on_top += s.normal == Vec3(0, 0, 1);
        }
    }
    EXPECT_NEAR(on_top / 1e4, 8.0 / 88, 0.01);
}

TEST(Box, SameHitsAtAnyScaleAndNoAcne) {
    check_scale_independence([](double s) {
        return std::make_unique<Box>(Vec3{-0.2, -1, 0.3} * s, Vec3{1, 0.5, 0.9} * s);
    });
}

TEST(Box, MinNotBelowMaxIsAPositionedError) {
    const std::string e = scene_error("objects:\n  - {type: box, min: [0, 0, 0], max: [1, -1, 1]}\n");
    EXPECT_NE(e.find("test.yaml:2:38: error: box max.y (-1) must be greater than min.y (0)"),
              std::string::npos)
        << e;
    EXPECT_NE(scene_error("objects:\n  - {type: box, min: [0, 0, 0], max: [1, 1, 0]}\n").find("max.z (0)"),
              std::string::npos);
    EXPECT_EQ(scene_error("objects:\n  - {type: box, min: [0, 0, 0], max: [1, 1, 1]}\n"), "");
}

}  // namespace
}  // namespace glint
