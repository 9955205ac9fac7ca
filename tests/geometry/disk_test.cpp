#include <gtest/gtest.h>

#include "geometry/shape_testing.hpp"
#include "glint/geometry/disk.hpp"

namespace glint {
namespace {

using testing::check_area_samples;
using testing::check_scale_independence;
using testing::scene_error;

TEST(Disk, HitsFromBothSidesWithTheGivenNormal) {
    const Disk disk({1, 2, 3}, {0, 0, 2}, 0.5);
    Hit hit;
    ASSERT_TRUE(disk.intersect({{1.1, 2.2, 10}, {0, 0, -1}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 7);
    EXPECT_EQ(hit.point, Vec3(1.1, 2.2, 3));
    EXPECT_EQ(hit.normal, Vec3(0, 0, 1));
    EXPECT_EQ(hit.shading_normal, Vec3(0, 0, 1));
    EXPECT_NEAR(hit.uv.y, std::sqrt(0.05) / 0.5, 1e-12);
    // From below: the same normal (open surface; shading faces it forward).
    ASSERT_TRUE(disk.intersect({{1, 2, 0}, {0, 0, 2}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 1.5);
    EXPECT_EQ(hit.normal, Vec3(0, 0, 1));
}

TEST(Disk, MissesOutsideTheRadiusBehindAndBeyondTMax) {
    const Disk disk({0, 0, 0}, {0, 1, 0}, 1);
    Hit hit;
    EXPECT_FALSE(disk.intersect({{1.01, 1, 0}, {0, -1, 0}}, kInf, hit));     // outside the rim
    EXPECT_TRUE(disk.intersect({{0.99, 1, 0}, {0, -1, 0}}, kInf, hit));      // inside it
    EXPECT_FALSE(disk.intersect({{0, 1, 0}, {0, 1, 0}}, kInf, hit));         // the disk is behind
    EXPECT_FALSE(disk.intersect({{0, 1, 0}, {0, -1, 0}}, 1.0, hit));         // t = 1 is not < t_max
    EXPECT_TRUE(disk.intersect({{0, 1, 0}, {0, -1, 0}}, 1.0 + 1e-12, hit));  // just within
    EXPECT_FALSE(disk.intersect({{0, 0, 0}, {0, -1, 0}}, kInf, hit));        // t = 0: no self-hit
    EXPECT_FALSE(disk.intersect({{-2, 0, 0}, {1, 0, 0}}, kInf, hit));        // grazing, in the plane
    EXPECT_FALSE(disk.occluded({{-2, 0, 0}, {1, 0, 0}}, kInf));
    EXPECT_TRUE(disk.occluded({{0.3, -1, 0.2}, {0, 1, 0}}, kInf));
    EXPECT_FALSE(disk.occluded({{0.3, -1, 0.2}, {0, 1, 0}}, 0.5));
}

TEST(Disk, AnnulusHasAHole) {
    const Disk ring({0, 0, 0}, {0, 1, 0}, 2, 1);
    Hit hit;
    EXPECT_FALSE(ring.intersect({{0.5, 1, 0}, {0, -1, 0}}, kInf, hit));
    EXPECT_TRUE(ring.intersect({{1.5, 1, 0}, {0, -1, 0}}, kInf, hit));
    EXPECT_FALSE(ring.intersect({{2.5, 1, 0}, {0, -1, 0}}, kInf, hit));
    EXPECT_NEAR(ring.area(), kPi * 3, 1e-12);
}

TEST(Disk, AreaSamplesAreUniformOnTheSurface) {
    const Vec3 c{1, -2, 0.5};
    const Vec3 n = normalize(Vec3{1, 2, 2});
    for (const double inner : {0.0, 0.7}) {
        const Disk disk(c, n, 1.5, inner);
        EXPECT_NEAR(disk.area(), kPi * (1.5 * 1.5 - inner * inner), 1e-12);
        const auto distance = [&](const Vec3& p) {
            const double off_plane = dot(p - c, n);
            const double r = length(p - c - off_plane * n);
            const double outside = std::max({0.0, r - 1.5, inner - r});
            return std::abs(off_plane) + outside;
        };
        const Vec3 mean = check_area_samples(disk, 64, distance, 1.5);
        EXPECT_NEAR(testing::distance(mean, c), 0, 1e-6);
        // Uniform by area: the fraction of samples within radius ρ is (ρ² − inner²)/(R² − inner²).
        int within = 0;
        const int n_side = 64;
        const double rho = 1.2;
        for (int i = 0; i < n_side; ++i) {
            for (int j = 0; j < n_side; ++j) {
                within += length(disk.sample_area({(i + 0.5) / n_side, (j + 0.5) / n_side})->point - c) < rho;
            }
        }
        EXPECT_NEAR(within / double(n_side * n_side),
                    (rho * rho - inner * inner) / (1.5 * 1.5 - inner * inner), 1.0 / n_side);
    }
}

TEST(Disk, SameHitsAtAnyScaleAndNoAcne) {
    check_scale_independence([](double s) {
        return std::make_unique<Disk>(Vec3{0.3, 0.1, -0.2} * s, Vec3{1, 3, -2}, 1.0 * s, 0.25 * s);
    });
}

TEST(Disk, SceneErrorsArePositioned) {
    EXPECT_NE(scene_error("objects:\n  - {type: disk, radius: 0}\n").find("test.yaml:2:26"),
              std::string::npos)
        << scene_error("objects:\n  - {type: disk, radius: 0}\n");
    const std::string e = scene_error("objects:\n  - {type: annulus, inner_radius: 2, outer_radius: 1}\n");
    EXPECT_NE(e.find("test.yaml:2:35: error: annulus inner_radius must be less than outer_radius"),
              std::string::npos)
        << e;
    EXPECT_EQ(
        scene_error("objects:\n  - {type: annulus, inner_radius: 1, outer_radius: 2, normal: [1, 0, 0]}\n"),
        "");
}

}  // namespace
}  // namespace glint
