// Embree and the BVH must agree ray for ray (built only when Embree is).
#ifdef GLINT_HAVE_EMBREE

#include <gtest/gtest.h>

#include "accel/accel_test_scenes.hpp"
#include "glint/accel/bvh.hpp"
#include "glint/accel/embree.hpp"
#include "glint/accel/linear.hpp"
#include "glint/geometry/plane.hpp"
#include "test_data.hpp"

namespace glint {
namespace {

using test::expect_same_hits;
using test::pointers;
using test::rays_into;

TEST(Embree, IsInTheTable) {
    EXPECT_NE(make_accelerator("embree", {}), nullptr);
}

TEST(Embree, RandomSpheresAndAPlaneGiveTheBvhsAndTheListsHits) {
    auto shapes = test::random_spheres(2000, 31);
    shapes.push_back(std::make_unique<Plane>(Vec3{0, -11, 0}, Vec3{0, 1, 0}));
    const auto ptrs = pointers(shapes);
    const LinearAccelerator list(ptrs);
    const BvhAccelerator bvh(ptrs);
    const EmbreeAccelerator embree(ptrs);
    const auto rays = rays_into(Bounds3{{-10, -10, -10}, {10, 10, 10}}, 3000, 12);
    expect_same_hits(list, embree, rays, ptrs);
    expect_same_hits(bvh, embree, rays, ptrs);
}

TEST(Embree, BunnyAndMeshesGiveTheBvhsHits) {
    GLINT_REQUIRE_DATA_FILE(bunny_file, "meshes/stanford-bunny.obj");
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Mesh>(load_mesh_file(bunny_file)));
    shapes.push_back(std::make_unique<Mesh>(test::tessellated_sphere(4, 0.03, {0.1, 0.1, 0.1})));
    shapes.push_back(std::make_unique<Sphere>(Vec3{-0.1, 0.1, 0}, 0.02));
    const auto ptrs = pointers(shapes);
    const BvhAccelerator bvh(ptrs);
    const EmbreeAccelerator embree(ptrs);
    expect_same_hits(bvh, embree, rays_into(bvh.bounds(), 3000, 13), ptrs, {true, 1e-5});
}

// Rays leaving a surface: Embree's float test can find the triangle a ray starts on, which the
// backend's double-precision filter must reject (else: false shadows and hits at t ≈ 0).
TEST(Embree, RaysLeavingTheBunnysSurfaceGiveTheBvhsAnswers) {
    GLINT_REQUIRE_DATA_FILE(bunny_file, "meshes/stanford-bunny.obj");
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Mesh>(load_mesh_file(bunny_file)));
    const auto ptrs = pointers(shapes);
    const BvhAccelerator bvh(ptrs);
    const EmbreeAccelerator embree(ptrs);
    const auto rays = test::surface_rays(
        bvh.bounds(), 20000, 29, [&](const Ray& ray, Hit& hit) { return bvh.intersect(ray, kInf, hit); });
    int differ = 0;
    for (const Ray& shadow : rays.shadow) {
        differ += bvh.occluded(shadow, 1.0) != embree.occluded(shadow, 1.0) ? 1 : 0;
    }
    EXPECT_EQ(differ, 0) << "of " << rays.shadow.size() << " shadow rays";
    for (const Ray& bounce : rays.bounce) {
        Hit a, b;
        const bool found = bvh.intersect(bounce, kInf, a);
        ASSERT_EQ(embree.intersect(bounce, kInf, b), found) << bounce.origin << " + t " << bounce.direction;
        if (found) {
            EXPECT_NEAR(a.t, b.t, 1e-12 * a.t);
        }
    }
}

TEST(Embree, NoRaySlipsThroughAClosedMesh) {
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Mesh>(test::tessellated_sphere(3, 2.0)));
    const auto ptrs = pointers(shapes);
    const EmbreeAccelerator embree(ptrs);
    const auto& mesh = static_cast<const Mesh&>(*shapes[0]);
    int rays = 0;
    for (const Vec3& vertex : mesh.positions()) {
        Hit hit;
        EXPECT_TRUE(embree.intersect({{0, 0, 0}, vertex}, kInf, hit)) << vertex;
        EXPECT_TRUE(embree.occluded({{0, 0, 0}, vertex}, kInf)) << vertex;
        ++rays;
    }
    EXPECT_EQ(rays, static_cast<int>(mesh.positions().size()));
}

}  // namespace
}  // namespace glint

#endif
