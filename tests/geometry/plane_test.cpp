#include "glint/geometry/plane.hpp"

#include <gtest/gtest.h>

namespace glint {
namespace {

TEST(Plane, HitFromEitherSide) {
    const Plane p({0, 1, 0}, {0, 2, 0});  // normal is normalised
    Hit hit;
    ASSERT_TRUE(p.intersect({{0, 5, 0}, {0, -1, 0}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 4.0);
    EXPECT_EQ(hit.normal, Vec3(0, 1, 0));
    ASSERT_TRUE(p.intersect({{3, -2, 1}, {0, 1, 0}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 3.0);
    EXPECT_DOUBLE_EQ(hit.point.y, 1.0);
}

TEST(Plane, ParallelAndBehindRaysMiss) {
    const Plane p({0, 0, 0}, {0, 1, 0});
    Hit hit;
    EXPECT_FALSE(p.intersect({{0, 1, 0}, {1, 0, 0}}, kInf, hit));
    EXPECT_FALSE(p.intersect({{0, 0, 0}, {1, 0, 0}}, kInf, hit));  // lying in the plane
    EXPECT_FALSE(p.intersect({{0, 1, 0}, {0, 1, 0}}, kInf, hit));
    EXPECT_FALSE(p.occluded({{0, 1, 0}, {0, -1, 0}}, 0.5));
    EXPECT_TRUE(p.occluded({{0, 1, 0}, {0, -1, 0}}, 1.5));
}

TEST(Plane, GrazingHitFarAwayStaysOnThePlane) {
    const Plane p({0, 0, 0}, {0, 1, 0});
    Hit hit;
    ASSERT_TRUE(p.intersect({{0, 1e-3, 0}, normalize(Vec3(1, -1e-9, 0))}, kInf, hit));
    EXPECT_NEAR(hit.point.x, 1e6, 1e-3);
    EXPECT_EQ(hit.point.y, 0.0);  // projected back onto the plane
    // A ray leaving it upwards does not hit it again.
    Hit again;
    EXPECT_FALSE(p.intersect(spawn_ray(hit, {0, 1, 0}), kInf, again));
}

}  // namespace
}  // namespace glint
