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
