#include <gtest/gtest.h>

#include "geometry/shape_testing.hpp"
#include "glint/geometry/cone.hpp"

namespace glint {
namespace {

using testing::check_area_samples;
using testing::check_random_hits;
using testing::check_scale_independence;
using testing::scene_error;

// A cone described the way the tests check it, independently of the code under test.
struct ConeModel {
    Vec3 base, apex;
    double radius;
    bool capped;

    Vec3 axis() const { return normalize(apex - base); }
    double height() const { return length(apex - base); }
    double slant() const { return std::hypot(radius, height()); }
    double z(const Vec3& p) const { return dot(p - base, axis()); }
    Vec3 radial(const Vec3& p) const { return p - base - z(p) * axis(); }

    // Distance in the (ρ, z) half-plane to the segment from the rim (r, 0) to the apex (0, h).
    double side_distance(const Vec3& p) const {
        const double rho = length(radial(p)), z_ = z(p);
        const double along = std::clamp(((rho - radius) * -radius + z_ * height()) / slant(), 0.0, slant());
        return std::hypot(rho - (radius - along * radius / slant()), z_ - along * height() / slant());
    }
    double cap_distance(const Vec3& p) const {
        return std::hypot(std::max(0.0, length(radial(p)) - radius), z(p));
    }
    double distance(const Vec3& p) const {
        return capped ? std::min(side_distance(p), cap_distance(p)) : side_distance(p);
    }
    Vec3 normal(const Vec3& p) const {
        if (capped && cap_distance(p) < side_distance(p)) {
            return -axis();
        }
        return height() / slant() * normalize(radial(p)) + radius / slant() * axis();
    }
};

TEST(Cone, HitsTheSideAndCapWithOutwardNormals) {
    const Cone cone({0, 0, 0}, {0, 2, 0}, 1, true);  // side: ρ = 1 − y/2
    Hit hit;
    ASSERT_TRUE(cone.intersect({{-5, 1, 0}, {1, 0, 0}}, kInf, hit));
    EXPECT_NEAR(hit.t, 4.5, 1e-14);
    EXPECT_NEAR(testing::distance(hit.point, {-0.5, 1, 0}), 0, 1e-14);
    EXPECT_NEAR(testing::distance(hit.normal, Vec3(-2, 1, 0) / std::sqrt(5.0)), 0, 1e-14);
    ASSERT_TRUE(cone.intersect({{0, 0.5, 0}, {1, 0, 0}}, kInf, hit));  // from inside
    EXPECT_NEAR(hit.t, 0.75, 1e-14);
    EXPECT_NEAR(testing::distance(hit.normal, Vec3(2, 1, 0) / std::sqrt(5.0)), 0, 1e-14);
    ASSERT_TRUE(cone.intersect({{0.2, -3, 0.1}, {0, 1, 0}}, kInf, hit));  // the cap
    EXPECT_DOUBLE_EQ(hit.t, 3);
    EXPECT_EQ(hit.normal, Vec3(0, -1, 0));
    EXPECT_FALSE(cone.intersect({{-5, 2.5, 0}, {1, 0, 0}}, kInf, hit));   // above the apex: no second nappe
    EXPECT_FALSE(cone.intersect({{-5, -0.5, 0}, {1, 0, 0}}, kInf, hit));  // below the base
    EXPECT_FALSE(cone.intersect({{-5, 1, 0}, {1, 0, 0}}, 4.5, hit));      // t_max
    EXPECT_FALSE(cone.intersect({{-5, 1, 0}, {-1, 0, 0}}, kInf, hit));    // behind
    // Grazing: up along the outside of the rim, and along a side line just outside the cone.
    EXPECT_FALSE(cone.intersect({{1.000001, -1, 0}, {0, 1, 0}}, kInf, hit));
    EXPECT_FALSE(cone.intersect({{-1.000001, 0, 0}, {1, 2, 0}}, kInf, hit));
    EXPECT_FALSE(cone.occluded({{-1.000001, 0, 0}, {1, 2, 0}}, kInf));
    // The open cone: the ray up the axis from below passes its open base and meets the inside of
    // the apex region; the point is the apex.
    const Cone open({0, 0, 0}, {0, 2, 0}, 1, false);
    EXPECT_FALSE(open.intersect({{0.2, -3, 0.1}, {0, 1, 0}}, 3.5, hit));
    ASSERT_TRUE(open.intersect({{0.2, -3, 0}, {0, 1, 0}}, kInf, hit));
    EXPECT_NEAR(hit.t, 4.6, 1e-14);
}

TEST(Cone, RayParallelToTheSlant) {
    // a = 0 in the quadratic: the ray is parallel to one side line and meets the cone once.
    const Cone cone({0, 0, 0}, {0, 1, 0}, 1, false);  // ρ = 1 − y: side lines at 45°
    Hit hit;
    // Parallel to the left side line y = 1 + x, half a unit below it: it enters through the open base
    // and meets the right side y = 1 − x from inside.
    ASSERT_TRUE(cone.intersect({{-2, -1.5, 0}, {1, 1, 0}}, kInf, hit));
    EXPECT_NEAR(hit.t, 2.25, 1e-14);
    EXPECT_NEAR(testing::distance(hit.point, {0.25, 0.75, 0}), 0, 1e-14);
    EXPECT_NEAR(testing::distance(hit.normal, Vec3(1, 1, 0) / std::sqrt(2.0)), 0, 1e-14);
    // Above it: the other nappe, which is cut off.
    EXPECT_FALSE(cone.intersect({{-2, -0.5, 0}, {1, 1, 0}}, kInf, hit));
}

TEST(Cone, RandomHitsSatisfyTheImplicitEquation) {
    for (const bool capped : {true, false}) {
        const ConeModel m{{0.5, -1, 0.2}, {1.2, 1, -0.3}, 0.8, capped};
        const Cone c(m.base, m.apex, m.radius, m.capped);
        check_random_hits(
            c, [&](const Vec3& p) { return m.distance(p); }, [&](const Vec3& p) { return m.normal(p); });
    }
}

TEST(Cone, AreaSamplesAreUniform) {
    for (const bool capped : {true, false}) {
        const ConeModel m{{0.5, -1, 0.2}, {1.2, 1, -0.3}, 0.8, capped};
        const Cone c(m.base, m.apex, m.radius, m.capped);
        const double side = kPi * m.radius * m.slant();
        const double cap = kPi * m.radius * m.radius;
        EXPECT_NEAR(c.area(), side + (capped ? cap : 0), 1e-12);
        const Vec3 mean = check_area_samples(
            c, 120, [&](const Vec3& p) { return m.distance(p); }, 2.5);
        // The side's centroid is a third of the way up; the cap's is the base centre.
        const double z_mean = side * m.height() / 3 / (side + (capped ? cap : 0));
        EXPECT_NEAR(testing::distance(mean, m.base + z_mean * m.axis()), 0, 2e-3);
    }
}

TEST(Cone, SameHitsAtAnyScaleAndNoAcne) {
    for (const bool capped : {true, false}) {
        check_scale_independence([capped](double s) {
            return std::make_unique<Cone>(Vec3{0.1, -0.5, 0.2} * s, Vec3{-0.3, 0.8, 0.4} * s, 0.5 * s,
                                          capped);
        });
    }
}

TEST(Cone, ApexEqualToBaseIsAPositionedError) {
    const std::string e =
        scene_error("objects:\n  - {type: cone, base: [0, 1, 0], apex: [0, 1, 0], radius: 1}\n");
    EXPECT_NE(e.find("test.yaml:2:41: error: cone apex must differ from base"), std::string::npos) << e;
}

}  // namespace
}  // namespace glint
