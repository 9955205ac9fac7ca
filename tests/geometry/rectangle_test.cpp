#include <gtest/gtest.h>

#include "geometry/shape_testing.hpp"
#include "glint/geometry/rectangle.hpp"

namespace glint {
namespace {

using testing::check_area_samples;
using testing::check_scale_independence;
using testing::scene_error;

TEST(Rectangle, HitsWithNormalFromTheRightHandRuleAndUv) {
    const Rectangle rect({1, 0, 0}, {2, 0, 0}, {0, 0, -4});  // x in [1, 3], z in [−4, 0], y = 0
    Hit hit;
    ASSERT_TRUE(rect.intersect({{1.5, 5, -1}, {0, -1, 0}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 5);
    EXPECT_EQ(hit.point, Vec3(1.5, 0, -1));
    EXPECT_EQ(hit.normal, Vec3(0, 1, 0));  // (1,0,0) × (0,0,−1) = (0,1,0)
    EXPECT_NEAR(hit.uv.x, 0.25, 1e-15);
    EXPECT_NEAR(hit.uv.y, 0.25, 1e-15);
    ASSERT_TRUE(rect.intersect({{2.9, -1, -3.9}, {0, 2, 0}}, kInf, hit));  // from below
    EXPECT_DOUBLE_EQ(hit.t, 0.5);
    EXPECT_EQ(hit.normal, Vec3(0, 1, 0));
    EXPECT_FALSE(rect.intersect({{0.9, 1, -1}, {0, -1, 0}}, kInf, hit));  // beside edge1's start
    EXPECT_FALSE(rect.intersect({{2, 1, 0.1}, {0, -1, 0}}, kInf, hit));   // beyond the corner's side
    EXPECT_FALSE(rect.intersect({{2, 1, -4.1}, {0, -1, 0}}, kInf, hit));  // beyond edge2
    EXPECT_FALSE(rect.intersect({{2, 1, -1}, {0, 1, 0}}, kInf, hit));     // behind
    EXPECT_FALSE(rect.intersect({{2, 1, -1}, {0, -1, 0}}, 1, hit));       // t_max
    EXPECT_FALSE(rect.intersect({{0, 0, -1}, {1, 0, 0}}, kInf, hit));     // grazing, in the plane
    EXPECT_TRUE(rect.occluded({{2, 1, -1}, {0, -1, 0}}, 1.5));
    EXPECT_FALSE(rect.occluded({{2, 1, -1}, {0, -1, 0}}, 0.5));
}

TEST(Rectangle, ParallelogramSamplesAreUniform) {
    // A skewed parallelogram: area |e1 × e2|, centroid corner + (e1 + e2)/2.
    const Vec3 corner{-1, 2, 0.5}, e1{2, 0, 1}, e2{0.5, 1.5, 0};
    const Rectangle rect(corner, e1, e2);
    EXPECT_NEAR(rect.area(), length(cross(e1, e2)), 1e-12);
    const Vec3 n = normalize(cross(e1, e2));
    const auto distance = [&](const Vec3& p) { return std::abs(dot(p - corner, n)); };
    const Vec3 mean = check_area_samples(rect, 50, distance, 2);
    EXPECT_NEAR(testing::distance(mean, corner + 0.5 * (e1 + e2)), 0, 1e-9);
    // The samples' (a, b) coordinates are inside the unit square: hit from above gives them as uv.
    for (const Point2 u : {Point2{0.01, 0.99}, Point2{0.5, 0.25}}) {
        const Vec3 p = rect.sample_area(u)->point;
        Hit hit;
        ASSERT_TRUE(rect.intersect({p + n, -n}, kInf, hit));
        EXPECT_NEAR(hit.uv.x, u.x, 1e-12);
        EXPECT_NEAR(hit.uv.y, u.y, 1e-12);
    }
}

TEST(Rectangle, SameHitsAtAnyScaleAndNoAcne) {
    check_scale_independence([](double s) {
        return std::make_unique<Rectangle>(Vec3{-0.5, 0.2, 0.1} * s, Vec3{1, 0.3, 0} * s,
                                           Vec3{0.1, -0.2, 0.9} * s);
    });
}

TEST(Rectangle, ParallelOrZeroEdgesArePositionedErrors) {
    std::string e = scene_error(
        "objects:\n  - {type: rectangle, corner: [0, 0, 0], edge1: [1, 0, 0], edge2: [-2, 0, 0]}\n");
    EXPECT_NE(e.find("test.yaml:2:67: error: rectangle edge1 and edge2 are parallel"), std::string::npos)
        << e;
    e = scene_error(
        "objects:\n  - {type: rectangle, corner: [0, 0, 0], edge1: [0, 0, 0], edge2: [1, 0, 0]}\n");
    EXPECT_NE(e.find("test.yaml:2:49: error: rectangle edge1 must not be zero"), std::string::npos) << e;
    EXPECT_EQ(
        scene_error(
            "objects:\n  - {type: rectangle, corner: [0, 0, 0], edge1: [1e-6, 0, 0], edge2: [0, 1e-6, 0]}\n"),
        "");
}

}  // namespace
}  // namespace glint
