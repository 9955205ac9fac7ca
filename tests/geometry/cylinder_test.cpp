#include <gtest/gtest.h>

#include "geometry/shape_testing.hpp"
#include "glint/geometry/cylinder.hpp"

namespace glint {
namespace {

using testing::check_area_samples;
using testing::check_random_hits;
using testing::check_scale_independence;
using testing::scene_error;

// A cylinder described the way the tests check it, independently of the code under test.
struct CylinderModel {
    Vec3 base, top;
    double radius;
    bool capped;

    Vec3 axis() const { return normalize(top - base); }
    double height() const { return length(top - base); }
    double z(const Vec3& p) const { return dot(p - base, axis()); }
    Vec3 radial(const Vec3& p) const { return p - base - z(p) * axis(); }

    // Unsigned distance to the surface (wall, and caps when capped).
    double distance(const Vec3& p) const {
        const double z_out = std::max({0.0, -z(p), z(p) - height()});
        const double rho = length(radial(p));
        double d = std::hypot(rho - radius, z_out);  // the wall (a finite tube)
        if (capped) {
            for (const double cap_z : {0.0, height()}) {
                d = std::min(d, std::hypot(std::max(0.0, rho - radius), z(p) - cap_z));
            }
        }
        return d;
    }
    Vec3 normal(const Vec3& p) const {
        const double wall = std::abs(length(radial(p)) - radius);
        if (capped && std::min(std::abs(z(p)), std::abs(z(p) - height())) < wall) {
            return z(p) < 0.5 * height() ? -axis() : axis();
        }
        return normalize(radial(p));
    }
};

TEST(Cylinder, HitsTheWallAndCapsWithOutwardNormals) {
    const Cylinder capped({0, 0, 0}, {0, 2, 0}, 1, true);
    const Cylinder open({0, 0, 0}, {0, 2, 0}, 1, false);
    Hit hit;
    for (const Cylinder* c : {&capped, &open}) {
        ASSERT_TRUE(c->intersect({{-5, 1, 0}, {1, 0, 0}}, kInf, hit));
        EXPECT_DOUBLE_EQ(hit.t, 4);
        EXPECT_NEAR(testing::distance(hit.point, {-1, 1, 0}), 0, 1e-15);
        EXPECT_NEAR(testing::distance(hit.normal, {-1, 0, 0}), 0, 1e-15);
        EXPECT_NEAR(hit.uv.y, 0.5, 1e-15);
        ASSERT_TRUE(c->intersect({{0, 1, 0}, {1, 0, 0}}, kInf, hit));  // from inside: still outward
        EXPECT_DOUBLE_EQ(hit.t, 1);
        EXPECT_NEAR(testing::distance(hit.normal, {1, 0, 0}), 0, 1e-15);
        EXPECT_FALSE(c->intersect({{-5, 1, 0}, {-1, 0, 0}}, kInf, hit));     // behind
        EXPECT_FALSE(c->intersect({{-5, 1, 0}, {1, 0, 0}}, 4, hit));         // t_max
        EXPECT_FALSE(c->intersect({{-5, 2.001, 0}, {1, 0, 0}}, kInf, hit));  // above the top
        EXPECT_FALSE(
            c->intersect({{-1.001, 5, 0}, {0, -1, 0}}, kInf, hit));  // grazing, along the wall outside
    }
    // Along the axis, from above: the capped cylinder's top, and nothing for the open tube.
    ASSERT_TRUE(capped.intersect({{0.5, 5, 0}, {0, -1, 0}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 3);
    EXPECT_EQ(hit.normal, Vec3(0, 1, 0));
    EXPECT_FALSE(open.intersect({{0.5, 5, 0}, {0, -1, 0}}, kInf, hit));
    ASSERT_TRUE(capped.intersect({{0, 1, 0}, {0, -1, 0}}, kInf, hit));  // the base, from inside
    EXPECT_DOUBLE_EQ(hit.t, 1);
    EXPECT_EQ(hit.normal, Vec3(0, -1, 0));
    // A slanted ray through the open tube hits the far wall from inside.
    ASSERT_TRUE(open.intersect({{0, 3, 0}, {1, -2, 0}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 1);
    EXPECT_NEAR(testing::distance(hit.normal, {1, 0, 0}), 0, 1e-15);
}

TEST(Cylinder, RandomHitsSatisfyTheImplicitEquation) {
    for (const bool capped : {true, false}) {
        const CylinderModel m{{0.5, -1, 0.2}, {1.5, 1, -0.3}, 0.6, capped};
        const Cylinder c(m.base, m.top, m.radius, m.capped);
        check_random_hits(
            c, [&](const Vec3& p) { return m.distance(p); }, [&](const Vec3& p) { return m.normal(p); });
    }
}

TEST(Cylinder, AreaSamplesAreUniform) {
    for (const bool capped : {true, false}) {
        const CylinderModel m{{0.5, -1, 0.2}, {1.5, 1, -0.3}, 0.6, capped};
        const Cylinder c(m.base, m.top, m.radius, m.capped);
        const double wall = 2 * kPi * 0.6 * m.height();
        EXPECT_NEAR(c.area(), wall + (capped ? 2 * kPi * 0.36 : 0), 1e-12);
        const Vec3 mean = check_area_samples(
            c, 300, [&](const Vec3& p) { return m.distance(p); }, 2.5);
        // The grid quantises the parts' shares of u.x to 1/300: that much weight may move by a height.
        EXPECT_NEAR(testing::distance(mean, 0.5 * (m.base + m.top)), 0, m.height() / 300);
        // The wall's share of the samples is its share of the area.
        int on_wall = 0;
        for (int i = 0; i < 120; ++i) {
            for (int j = 0; j < 120; ++j) {
                const ShapeSample s = *c.sample_area({(i + 0.5) / 120, (j + 0.5) / 120});
                EXPECT_NEAR(testing::distance(s.normal, m.normal(s.point)), 0, 1e-9);
                on_wall += std::abs(dot(s.normal, m.axis())) < 0.5;
            }
        }
        EXPECT_NEAR(on_wall / (120.0 * 120.0), wall / c.area(), 1.0 / 120);
    }
}

TEST(Cylinder, SameHitsAtAnyScaleAndNoAcne) {
    for (const bool capped : {true, false}) {
        check_scale_independence([capped](double s) {
            return std::make_unique<Cylinder>(Vec3{0.1, -0.5, 0.2} * s, Vec3{-0.3, 0.8, 0.4} * s, 0.4 * s,
                                              capped);
        });
    }
}

TEST(Cylinder, SceneErrorsArePositioned) {
    std::string e =
        scene_error("objects:\n  - {type: cylinder, base: [1, 2, 3], top: [1, 2, 3], radius: 1}\n");
    EXPECT_NE(e.find("test.yaml:2:44: error: cylinder top must differ from base"), std::string::npos) << e;
    e = scene_error("objects:\n  - {type: cylinder, radius: 1, capped: maybe}\n");
    EXPECT_NE(e.find("test.yaml:2:41: error: cylinder.capped must be true or false"), std::string::npos) << e;
    EXPECT_EQ(
        scene_error(
            "objects:\n  - {type: cylinder, base: [0, 0, 0], top: [0, 0, 1], radius: 1, capped: false}\n"),
        "");
}

}  // namespace
}  // namespace glint
