#include <gtest/gtest.h>

#include "glint/core/hash.hpp"
#include "glint/core/transform.hpp"

namespace glint {
namespace {

double distance(const Vec3& a, const Vec3& b) {
    return length(a - b);
}

TEST(Transform, RotationFollowsTheRightHandRule) {
    const Transform r = Transform::rotate({0, 0, 2}, 90);
    EXPECT_NEAR(distance(r.point({1, 0, 0}), {0, 1, 0}), 0, 1e-15);
    EXPECT_NEAR(distance(r.point({0, 1, 0}), {-1, 0, 0}), 0, 1e-15);
    EXPECT_NEAR(distance(Transform::rotate({1, 0, 0}, 90).vector({0, 1, 0}), {0, 0, 1}), 0, 1e-15);
    EXPECT_NEAR(distance(Transform::rotate({0, 1, 0}, 90).vector({0, 0, 1}), {1, 0, 0}), 0, 1e-15);
}

TEST(Transform, ThenAppliesInOrder) {
    const Transform scale_then_move = Transform::scale({2, 2, 2})->then(Transform::translate({1, 0, 0}));
    EXPECT_EQ(scale_then_move.point({1, 0, 0}), Vec3(3, 0, 0));
    const Transform move_then_scale = Transform::translate({1, 0, 0}).then(*Transform::scale({2, 2, 2}));
    EXPECT_EQ(move_then_scale.point({1, 0, 0}), Vec3(4, 0, 0));
    // Directions ignore the translation.
    EXPECT_EQ(scale_then_move.vector({1, 0, 0}), Vec3(2, 0, 0));
}

TEST(Transform, InverseUndoesRandomCompositions) {
    for (std::uint32_t i = 0; i < 200; ++i) {
        const SampleKey key{3, i, 0, 0};
        const auto u = [&](std::uint32_t d) { return 2 * key.uniform(d) - 1; };
        const Transform t =
            Transform::scale({0.5 + key.uniform(0), -0.2 - key.uniform(1), 3 * key.uniform(2) + 0.1})
                ->then(Transform::rotate({u(3), u(4), u(5)}, 360 * key.uniform(6)))
                .then(Transform::translate({10 * u(7), 10 * u(8), 10 * u(9)}));
        const Vec3 p{u(10), u(11), u(12)};
        EXPECT_NEAR(distance(t.inverse_point(t.point(p)), p), 0, 1e-12);
        EXPECT_NEAR(distance(t.inverse().point(t.point(p)), p), 0, 1e-12);
        EXPECT_NEAR(distance(t.inverse_vector(t.vector(p)), p), 0, 1e-12);
        // Normals stay perpendicular to transformed tangents (the inverse transpose).
        const Vec3 tangent1{u(13), u(14), u(15)}, tangent2{u(16), u(17), u(18)};
        const Vec3 n = t.normal(cross(tangent1, tangent2));
        EXPECT_NEAR(dot(n, t.vector(tangent1)) / length(n), 0, 1e-12);
        EXPECT_NEAR(dot(n, t.vector(tangent2)) / length(n), 0, 1e-12);
        // from_matrix inverts the same matrix independently.
        const std::optional<Transform> again = Transform::from_matrix(t.matrix());
        ASSERT_TRUE(again);
        EXPECT_NEAR(distance(again->inverse_point(t.point(p)), p), 0, 1e-12);
    }
}

TEST(Transform, SingularMatricesAreRefusedAtAnyScale) {
    EXPECT_FALSE(Transform::scale({1, 0, 1}));
    EXPECT_FALSE(Transform::from_matrix({{{1, 2, 3, 0}, {2, 4, 6, 0}, {0, 0, 1, 0}}}));  // two parallel rows
    EXPECT_TRUE(Transform::scale({1e-9, 1e-9, 1e-9}));                                   // tiny but not flat
    EXPECT_TRUE(Transform::scale({1e-6, 1, 1e6}));
}

TEST(Transform, BoundsHoldTheTransformedBox) {
    const Transform t = Transform::rotate({0, 0, 1}, 45).then(Transform::translate({1, 2, 3}));
    const Bounds3 b = t.bounds({{-1, -1, -1}, {1, 1, 1}});
    EXPECT_NEAR(b.lo.x, 1 - std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(b.hi.y, 2 + std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(b.hi.z, 4, 1e-12);
    EXPECT_FALSE(t.bounds(Bounds3::infinite()).is_finite());
}

TEST(Transform, UniformScaleIsRecognised) {
    const Transform similar = Transform::scale({-2, -2, -2})->then(Transform::rotate({1, 1, 0}, 33));
    ASSERT_TRUE(similar.uniform_scale());
    EXPECT_NEAR(*similar.uniform_scale(), 2, 1e-12);
    EXPECT_FALSE(Transform::scale({1, 2, 1})->uniform_scale());
}

}  // namespace
}  // namespace glint
