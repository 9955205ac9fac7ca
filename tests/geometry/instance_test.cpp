#include <gtest/gtest.h>

#include "geometry/shape_testing.hpp"
#include "glint/geometry/box.hpp"
#include "glint/geometry/disk.hpp"
#include "glint/geometry/instance.hpp"
#include "glint/geometry/sphere.hpp"
#include "glint/geometry/torus.hpp"
#include "glint/scene/scene.hpp"

namespace glint {
namespace {

using testing::check_random_hits;
using testing::check_scale_independence;
using testing::scene_error;

// A rotation by `degrees` about z, written out (not through Transform).
Vec3 rotate_z(const Vec3& v, double degrees) {
    const double c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
    return {c * v.x - s * v.y, s * v.x + c * v.y, v.z};
}

TEST(Instance, ScaledSphereIsTheEllipsoid) {
    // Semi-axes (2, 1, 0.5), turned 30° about z, centred at c: x'ᵀ diag(1/a²) x' = 1 with
    // x' = R⁻¹ (x − c); the gradient diag(1/a²) x' turned back by R is the normal.
    const Vec3 axes{2, 1, 0.5}, c{1, -2, 3};
    const Transform t =
        Transform::scale(axes)->then(Transform::rotate({0, 0, 1}, 30)).then(Transform::translate(c));
    const Instance ellipsoid(std::make_unique<Sphere>(Vec3{}, 1), t);
    const auto local = [&](const Vec3& p) { return rotate_z(p - c, -30); };
    const auto implicit_distance = [&](const Vec3& p) {
        const Vec3 q = local(p);
        // Algebraic distance, scaled by the smallest semi-axis into a length near the surface.
        return (std::sqrt(sqr(q.x / axes.x) + sqr(q.y / axes.y) + sqr(q.z / axes.z)) - 1) * 0.5;
    };
    const auto normal = [&](const Vec3& p) {
        const Vec3 q = local(p);
        return normalize(rotate_z({q.x / sqr(axes.x), q.y / sqr(axes.y), q.z / sqr(axes.z)}, 30));
    };
    check_random_hits(ellipsoid, implicit_distance, normal, 1000);
    // The tip of the long axis, from far along it: t in the world's units.
    Hit hit;
    const Vec3 tip_direction = rotate_z({1, 0, 0}, 30);
    ASSERT_TRUE(ellipsoid.intersect({c + 10 * tip_direction, -tip_direction}, kInf, hit));
    EXPECT_NEAR(hit.t, 8, 1e-12);
    EXPECT_NEAR(testing::distance(hit.normal, tip_direction), 0, 1e-12);
    // From inside: outward normal along z, at the short semi-axis.
    ASSERT_TRUE(ellipsoid.intersect({c, {0, 0, 2}}, kInf, hit));
    EXPECT_NEAR(hit.t, 0.25, 1e-12);
    EXPECT_NEAR(testing::distance(hit.normal, {0, 0, 1}), 0, 1e-12);
    EXPECT_FALSE(ellipsoid.intersect({c, {0, 0, 2}}, 0.25, hit));  // t_max
    // Bounds hold the ellipsoid.
    const Bounds3 b = ellipsoid.bounds();
    EXPECT_LE(b.hi.z, c.z + 0.5 + 1e-12);
    EXPECT_GE(b.hi.z, c.z + 0.5 - 1e-12);
}

TEST(Instance, SphereUvIsTheSpheresOwnNotTheWorldNormals) {
    // A unit sphere turned 90° about z: the world's +x is the sphere's −y, its south pole (v = 1).
    const Instance turned(std::make_unique<Sphere>(Vec3{}, 1), Transform::rotate({0, 0, 1}, 90));
    Hit hit;
    ASSERT_TRUE(turned.intersect({{5, 0, 0}, {-1, 0, 0}}, kInf, hit));
    EXPECT_FALSE(uv_deferred(hit));  // resolved before the normal left the sphere's space
    EXPECT_NEAR(surface_uv(hit).y, 1.0, 1e-7);
    // The world's +z is the sphere's own +z: u = ¼, v = ½.
    ASSERT_TRUE(turned.intersect({{0, 0, 5}, {0, 0, -1}}, kInf, hit));
    EXPECT_NEAR(surface_uv(hit).x, 0.25, 1e-12);
    EXPECT_NEAR(surface_uv(hit).y, 0.5, 1e-12);
}

TEST(Instance, RotatedBox) {
    // [−1, 1]³ turned 45° about z: a ray along +x at y = 0.5 enters through the face whose local
    // normal is +y (world (−1, 1, 0)/√2) where −x sin45° + 0.5 cos45° = 1, i.e. x = 0.5 − √2.
    const Instance box(std::make_unique<Box>(Vec3{-1, -1, -1}, Vec3{1, 1, 1}),
                       Transform::rotate({0, 0, 1}, 45));
    Hit hit;
    ASSERT_TRUE(box.intersect({{-10, 0.5, 0}, {1, 0, 0}}, kInf, hit));
    EXPECT_NEAR(hit.t, 10.5 - std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(testing::distance(hit.normal, Vec3(-1, 1, 0) / std::sqrt(2.0)), 0, 1e-12);
    const auto local = [](const Vec3& p) { return rotate_z(p, -45); };
    check_random_hits(
        box,
        [&](const Vec3& p) {
            const Vec3 q = abs(local(p)) - Vec3{1, 1, 1};
            return length(max(q, Vec3{})) + std::min(max_component(q), 0.0);
        },
        [&](const Vec3& p) {
            const Vec3 q = local(p);
            const Vec3 a = abs(q);
            const int axis = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
            Vec3 n;
            n[axis] = q[axis] > 0 ? 1 : -1;
            return rotate_z(n, 45);
        });
}

// A box that is not a Box to Instance, which so takes its general path: optionally with its shading
// normal tilted off the geometric one.
class DisguisedBox final : public Shape {
  public:
    DisguisedBox(const Vec3& lo, const Vec3& hi, bool tilt_shading)
        : box_(lo, hi), tilt_shading_(tilt_shading) {}
    Bounds3 bounds() const override { return box_.bounds(); }
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override {
        if (!box_.intersect(ray, t_max, hit)) {
            return false;
        }
        if (tilt_shading_) {
            hit.shading_normal = normalize(hit.normal + Vec3{0.25, -0.5, 0.125});
        }
        return true;
    }
    bool occluded(const Ray& ray, double t_max) const override { return box_.occluded(ray, t_max); }

  private:
    Box box_;
    bool tilt_shading_;
};

TEST(Instance, BoxesTakeTheirOwnPathToTheSameHitsBitForBit) {
    const Vec3 lo{-1, -2, 0.5}, hi{2, 1, 3};
    Transform::Matrix shear{{{1.5, 0.25, -0.5, 3}, {0.125, 2, 0.75, -1}, {-0.25, 0.5, 0.8, 2}}};
    const Transform transforms[] = {
        Transform::rotate({0, 1, 0}, 15).then(Transform::translate({265, 0, 295})),
        Transform::scale({2, 2, 2})
            ->then(Transform::rotate({1, 2, 3}, -70))
            .then(Transform::translate({1, 2, 3})),
        *Transform::from_matrix(shear)};
    for (const Transform& to_world : transforms) {
        const Instance fast(std::make_unique<Box>(lo, hi), to_world);
        const Instance general(std::make_unique<DisguisedBox>(lo, hi, false), to_world);
        Bounds3 around = fast.bounds();
        around = {around.lo - around.extent(), around.hi + around.extent()};
        int hits = 0;
        for (std::uint32_t i = 0; i < 20000; ++i) {
            // From around the box or from inside it, towards anywhere.
            const Vec3 origin = i % 4 == 0 ? to_world.point(testing::random_point_in({lo, hi}, 3, i))
                                           : testing::random_point_in(around, 3, i);
            const Ray ray{origin, testing::random_direction(3, i) * (0.5 + testing::uniform(3, i, 5))};
            const double t_max = i % 2 == 0 ? kInf : 10 * testing::uniform(3, i, 6);
            // Records that held another hit: what a miss leaves, and what a hit overwrites.
            Hit a, b;
            a.t = b.t = 1e300;
            a.primitive = b.primitive = 7;
            a.element = b.element = 9;
            const bool found = fast.intersect(ray, t_max, a);
            ASSERT_EQ(general.intersect(ray, t_max, b), found) << i;
            ASSERT_EQ(fast.occluded(ray, t_max), found) << i;
            hits += found;
            ASSERT_EQ(a.t, b.t) << i;
            ASSERT_EQ(a.point, b.point) << i;
            ASSERT_EQ(a.normal, b.normal) << i;
            ASSERT_EQ(a.shading_normal, b.shading_normal) << i;
            ASSERT_EQ(a.uv, b.uv) << i;
            ASSERT_EQ(a.error, b.error) << i;
            ASSERT_EQ(a.primitive, b.primitive) << i;
            ASSERT_EQ(a.element, b.element) << i;
        }
        EXPECT_GT(hits, 5000);
    }
}

TEST(Instance, ShadingNormalsOffTheGeometricOnesTurnOnTheirOwn) {
    const Transform to_world =
        *Transform::from_matrix({{{1.5, 0.25, -0.5, 3}, {0.125, 2, 0.75, -1}, {-0.25, 0.5, 0.8, 2}}});
    const DisguisedBox tilted(Vec3{-1, -1, -1}, Vec3{1, 1, 1}, true);
    const Instance instance(std::make_unique<DisguisedBox>(Vec3{-1, -1, -1}, Vec3{1, 1, 1}, true), to_world);
    const Ray local{{0.25, 0.5, -5}, {0, 0, 1}};
    Hit in_space, in_world;
    ASSERT_TRUE(tilted.intersect(local, kInf, in_space));
    ASSERT_TRUE(
        instance.intersect({to_world.point(local.origin), to_world.vector(local.direction)}, kInf, in_world));
    EXPECT_EQ(in_world.normal, normalize(to_world.normal(in_space.normal)));
    EXPECT_EQ(in_world.shading_normal, normalize(to_world.normal(in_space.shading_normal)));
    EXPECT_NE(in_world.shading_normal, in_world.normal);
}

TEST(Instance, AreaAndSamplesOnlyForSimilarities) {
    const Transform similar = Transform::scale({3, 3, 3})->then(Transform::rotate({1, 0, 0}, 90));
    const Instance disk(std::make_unique<Disk>(Vec3{}, Vec3{0, 1, 0}, 1), similar);
    EXPECT_NEAR(disk.area(), 9 * kPi, 1e-12);
    const std::optional<ShapeSample> s = disk.sample_area({0.3, 0.7});
    ASSERT_TRUE(s);
    EXPECT_NEAR(s->pdf_area, 1 / (9 * kPi), 1e-15);
    EXPECT_NEAR(s->point.z, 0, 1e-12);  // the disk's plane y = 0 turned onto z = 0
    EXPECT_NEAR(testing::distance(s->normal, {0, 0, 1}), 0, 1e-12);
    const Vec3 mean = testing::check_area_samples(
        disk, 40, [](const Vec3& p) { return std::abs(p.z); }, 3);
    EXPECT_NEAR(length(mean), 0, 1e-6);
    const Instance stretched(std::make_unique<Disk>(Vec3{}, Vec3{0, 1, 0}, 1), *Transform::scale({1, 1, 2}));
    EXPECT_EQ(stretched.area(), 0);
    EXPECT_FALSE(stretched.sample_area({0.3, 0.7}));
}

TEST(Instance, SameHitsAtAnyScaleAndNoAcne) {
    // An anisotropic, rotated, moved torus: the error bound must follow the transform.
    check_scale_independence([](double s) {
        const Transform t = Transform::scale(Vec3{1, 0.3, 2} * s)
                                ->then(Transform::rotate({1, 2, 3}, 40))
                                .then(Transform::translate(Vec3{0.5, -1, 0.25} * s));
        return std::make_unique<Instance>(std::make_unique<Torus>(Vec3{}, Vec3{0, 1, 0}, 1, 0.3), t);
    });
    // A strongly flattened ellipsoid (1000:1).
    check_scale_independence([](double s) {
        return std::make_unique<Instance>(std::make_unique<Sphere>(Vec3{}, 1),
                                          *Transform::scale(Vec3{1, 0.001, 0.5} * s));
    });
}

// The t at which the scene's first object is hit by a ray from (10, 0, 0) towards −x.
double hit_from_plus_x(const std::string& object) {
    const Scene scene = build_scene(parse_scene_text("objects:\n  - " + object + "\n", "test.yaml", "."));
    Hit hit;
    EXPECT_TRUE(scene.world->intersect({{10, 0, 0}, {-1, 0, 0}}, kInf, hit)) << object;
    return hit.t;
}

TEST(Instance, SceneTransformsApplyInTheDocumentedOrder) {
    // One map: scale, then rotate, then translate, whatever order the keys are written in.
    EXPECT_NEAR(hit_from_plus_x("{type: sphere, radius: 1, transform: {translate: [1, 0, 0], scale: 2}}"), 7,
                1e-12);
    // A list: in list order. Moved to x = 1 then scaled ×2: centre x = 2, radius 2.
    EXPECT_NEAR(hit_from_plus_x("{type: sphere, radius: 1, transform: [{translate: [1, 0, 0]}, {scale: 2}]}"),
                6, 1e-12);
    // Rotation: the box [0, 1]×[−0.5, 0.5]×[−0.5, 0.5] turned 180° about y spans x ∈ [−1, 0].
    EXPECT_NEAR(hit_from_plus_x("{type: box, min: [0, -0.5, -0.5], max: [1, 0.5, 0.5], "
                                "transform: {rotate: {axis: [0, 1, 0], angle: 180}}}"),
                10, 1e-12);
    // A 12-number matrix, row-major: x ↦ 3x + 1.
    EXPECT_NEAR(hit_from_plus_x(
                    "{type: sphere, radius: 1, transform: {matrix: [3, 0, 0, 1, 0, 3, 0, 0, 0, 0, 3, 0]}}"),
                6, 1e-12);
    EXPECT_NEAR(
        hit_from_plus_x("{type: sphere, radius: 1, transform: {matrix: [3, 0, 0, 1, 0, 3, 0, 0, 0, 0, 3, 0, "
                        "0, 0, 0, 1]}}"),
        6, 1e-12);
}

TEST(Instance, BadTransformsArePositionedErrors) {
    const auto error = [](const std::string& transform) {
        return scene_error("objects:\n  - {type: sphere, radius: 1, transform: " + transform + "}\n");
    };
    const auto expect = [&](const std::string& transform, const std::string& wanted) {
        const std::string e = error(transform);
        EXPECT_NE(e.find(wanted), std::string::npos) << transform << " gave: " << e;
    };
    expect("{scale: 0}", "test.yaml:2:50: error: sphere.transform.scale must not be zero");
    expect("{scale: [1, 0, 1]}", "test.yaml:2:50: error: sphere.transform.scale must not be zero");
    expect("[{translate: [1, 2, 3]}, {scale: [0, 1, 1]}]",
           "test.yaml:2:75: error: sphere.transform[1].scale must not");
    expect("{rotation: {axis: [0, 1, 0], angle: 3}}", "test.yaml:2:43: error: unknown key 'rotation'");
    expect("{rotation: {axis: [0, 1, 0], angle: 3}}", "expected one of: matrix, rotate, scale, translate");
    expect("{rotate: {axis: [0, 0, 0], angle: 3}}",
           "test.yaml:2:58: error: sphere.transform.rotate.axis must be a non-zero");
    expect("{rotate: {axis: [0, 1, 0]}}", "needs 'angle'");
    expect("{matrix: [1, 2, 3]}",
           "test.yaml:2:51: error: sphere.transform.matrix must be a list of 12 or 16 numbers");
    expect("{matrix: [1, 2, 3, 0, 2, 4, 6, 0, 0, 0, 1, 0]}",
           "test.yaml:2:51: error: sphere.transform.matrix cannot be inverted");
    expect("{matrix: [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1]}", "last row must be 0, 0, 0, 1");
    expect("{matrix: [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0], scale: 2}", "has both matrix and scale");
    expect("5", "test.yaml:2:42: error: sphere.transform must be a map");
    EXPECT_EQ(error("{scale: [-1, 2, 1], rotate: {axis: [1, 1, 1], angle: -20}, translate: [0, 1, 0]}"), "");
}

}  // namespace
}  // namespace glint
