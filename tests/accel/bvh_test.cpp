// The BVH must give the hits the brute-force list gives: same primitive, same t, for thousands of rays,
// and no ray may slip through a closed mesh at a shared edge or vertex.
#include <gtest/gtest.h>

#include "accel/accel_test_scenes.hpp"
#include "glint/accel/bvh.hpp"
#include "glint/accel/linear.hpp"
#include "glint/geometry/mesh_io/mesh_data.hpp"
#include "glint/geometry/plane.hpp"
#include "glint/geometry/triangle.hpp"
#include "test_data.hpp"

namespace glint {
namespace {

using test::expect_same_hits;
using test::pointers;
using test::random_direction;
using test::random_in_box;
using test::rays_into;

TEST(Bvh, RandomSpheresGiveTheListsHits) {
    const auto shapes = test::random_spheres(2000, 7);
    const auto ptrs = pointers(shapes);
    const LinearAccelerator list(ptrs);
    const BvhAccelerator bvh(ptrs);
    expect_same_hits(list, bvh, rays_into(list.bounds(), 3000, 11), ptrs);
    // Rays starting inside the cloud, in every direction.
    std::mt19937_64 rng(5);
    std::vector<Ray> inside;
    for (int i = 0; i < 2000; ++i) {
        inside.push_back({random_in_box(rng, {-9, -9, -9}, {9, 9, 9}), random_direction(rng)});
    }
    expect_same_hits(list, bvh, inside, ptrs);
}

TEST(Bvh, PlanesAreKeptOutsideTheTreeAndStillHit) {
    auto shapes = test::random_spheres(300, 3);
    shapes.push_back(std::make_unique<Plane>(Vec3{0, -11, 0}, Vec3{0, 1, 0}));
    shapes.push_back(std::make_unique<Plane>(Vec3{0, 0, 12}, Vec3{0.2, 0.1, 1}));
    const auto ptrs = pointers(shapes);
    const LinearAccelerator list(ptrs);
    const BvhAccelerator bvh(ptrs);
    EXPECT_EQ(bvh.unbounded_count(), 2u);
    std::mt19937_64 rng(9);
    std::vector<Ray> rays;
    for (int i = 0; i < 2000; ++i) {
        rays.push_back({random_in_box(rng, {-10, -10, -10}, {10, 10, 10}), random_direction(rng)});
    }
    expect_same_hits(list, bvh, rays, ptrs);
}

TEST(Bvh, EmptySceneAndSingleShape) {
    const BvhAccelerator empty(std::span<const Shape* const>{});
    Hit hit;
    EXPECT_FALSE(empty.intersect({{0, 0, 0}, {0, 0, 1}}, kInf, hit));
    EXPECT_FALSE(empty.occluded({{0, 0, 0}, {0, 0, 1}}, kInf));
    const Sphere sphere({0, 0, 5}, 1);
    const Shape* one[] = {&sphere};
    const BvhAccelerator bvh(one);
    ASSERT_TRUE(bvh.intersect({{0, 0, 0}, {0, 0, 1}}, kInf, hit));
    EXPECT_DOUBLE_EQ(hit.t, 4.0);
    EXPECT_FALSE(bvh.intersect({{0, 0, 0}, {0, 0, 1}}, 4.0, hit));  // t_max is exclusive
    EXPECT_FALSE(bvh.occluded({{0, 0, 0}, {0, 0, 1}}, 3.9));
}

// The reference for a mesh: every triangle tested, no BVH.
bool brute_force(const Mesh& mesh, const Ray& ray, TriangleHit& best, std::uint32_t& element,
                 double t_max = kInf) {
    const WatertightRay wray(ray);
    bool found = false;
    for (std::uint32_t i = 0; i < mesh.triangles().size(); ++i) {
        const auto& tri = mesh.triangles()[i];
        if (intersect_triangle(wray, mesh.positions()[tri[0]], mesh.positions()[tri[1]],
                               mesh.positions()[tri[2]], t_max, best)) {
            t_max = best.t;
            element = i;
            found = true;
        }
    }
    return found;
}

const Mesh& bunny(const std::filesystem::path& file) {
    static const Mesh mesh(load_mesh_file(file));
    return mesh;
}

// Checks the mesh's nearest hits and any-hit answers on `rays` against brute_force; returns how many hit.
int expect_brute_force_hits(const Mesh& mesh, const std::vector<Ray>& rays) {
    int hits = 0;
    for (const Ray& ray : rays) {
        TriangleHit reference;
        std::uint32_t element = 0;
        const bool found = brute_force(mesh, ray, reference, element);
        Hit hit;
        EXPECT_EQ(mesh.intersect(ray, kInf, hit), found);
        EXPECT_EQ(mesh.occluded(ray, kInf), found);
        if (found) {
            ++hits;
            EXPECT_EQ(hit.element, element);
            EXPECT_EQ(hit.t, reference.t);
        }
    }
    return hits;
}

TEST(Bvh, BunnyMeshGivesTheBruteForceHits) {
    GLINT_REQUIRE_DATA_FILE(bunny_file, "meshes/stanford-bunny.obj");
    const Mesh& mesh = bunny(bunny_file);
    ASSERT_EQ(mesh.triangles().size(), 69451u);  // the file's header says 69451 faces
    EXPECT_GT(expect_brute_force_hits(mesh, rays_into(mesh.bounds(), 150, 3)), 25);
}

// Rays that start on the surface, as shadow and bounce rays do: the any-hit traversal visits children
// in node order, not nearest first, and must still find an occluder whenever there is one.
TEST(Bvh, RaysLeavingTheBunnysSurfaceGiveTheBruteForceAnswers) {
    GLINT_REQUIRE_DATA_FILE(bunny_file, "meshes/stanford-bunny.obj");
    const Mesh& mesh = bunny(bunny_file);
    const auto rays = test::surface_rays(
        mesh.bounds(), 400, 23, [&](const Ray& ray, Hit& hit) { return mesh.intersect(ray, kInf, hit); });
    int occluded = 0;
    for (const Ray& shadow : rays.shadow) {
        TriangleHit unused;
        std::uint32_t element = 0;
        const bool blocked = brute_force(mesh, shadow, unused, element, 1.0);
        EXPECT_EQ(mesh.occluded(shadow, 1.0), blocked);
        occluded += blocked ? 1 : 0;
    }
    const int bounced = expect_brute_force_hits(mesh, rays.bounce);
    // Both answers occur often enough for the comparison to mean something.
    EXPECT_GT(occluded, 40);
    EXPECT_GT(static_cast<int>(rays.shadow.size()) - occluded, 40);
    EXPECT_GT(bounced, 20);
}

TEST(Bvh, BunnyHitsDoNotDependOnTheScale) {
    GLINT_REQUIRE_DATA_FILE(bunny_file, "meshes/stanford-bunny.obj");
    const MeshData original = load_mesh_file(bunny_file);
    const Mesh unit(original);
    for (double scale : {0.1, 1000.0}) {
        MeshData scaled = original;
        for (Vec3& p : scaled.positions) {
            p *= scale;
        }
        const Mesh mesh(std::move(scaled));
        for (const Ray& ray : rays_into(unit.bounds(), 500, 17)) {
            Hit a, b;
            const bool found = unit.intersect(ray, kInf, a);
            ASSERT_EQ(mesh.intersect({ray.origin * scale, ray.direction}, kInf, b), found);
            if (found) {
                EXPECT_EQ(a.element, b.element);
                EXPECT_NEAR(a.t * scale, b.t, 1e-9 * b.t);
            }
        }
    }
}

// Rays aimed exactly at vertices and at points of edges of a closed mesh, from outside, must all hit
// from outside and from inside.
void expect_watertight(const Mesh& mesh, const Vec3& center, double outside_distance, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    int rays = 0;
    for (const auto& tri : mesh.triangles()) {
        for (int k = 0; k < 3; ++k) {
            const Vec3& a = mesh.positions()[tri[static_cast<std::size_t>(k)]];
            const Vec3& b = mesh.positions()[tri[static_cast<std::size_t>((k + 1) % 3)]];
            for (const Vec3& target : {a, 0.5 * (a + b), a + u(rng) * (b - a)}) {
                // From outside, through the target; and from the centre, out through it. The outside
                // origin lies roughly along the outward direction, so the ray crosses the surface at
                // the target rather than grazing a silhouette (where rounding may rightly miss).
                const Vec3 outward = normalize(target - center) + 0.3 * random_direction(rng);
                const Vec3 origin = target + outside_distance * normalize(outward);
                const Ray in{origin, target - origin};
                const Ray out{center, target - center};
                Hit hit;
                TriangleHit reference;
                std::uint32_t element = 0;
                EXPECT_TRUE(brute_force(mesh, in, reference, element)) << "every triangle missed " << target;
                EXPECT_TRUE(mesh.intersect(in, kInf, hit)) << "slipped in through " << target;
                EXPECT_TRUE(mesh.occluded(in, kInf));
                EXPECT_TRUE(mesh.intersect(out, kInf, hit)) << "slipped out through " << target;
                EXPECT_TRUE(mesh.occluded(out, kInf));
                rays += 2;
            }
        }
    }
    EXPECT_GE(rays, 6 * 3 * static_cast<int>(mesh.triangles().size()));
}

TEST(Bvh, NoRaySlipsThroughAClosedTessellatedSphere) {
    const Mesh mesh(test::tessellated_sphere(3, 2.0, {0.3, -0.2, 0.1}));
    expect_watertight(mesh, {0.3, -0.2, 0.1}, 10, 1);
}

TEST(Bvh, NoRaySlipsThroughAClosedCubeEvenAlongTheAxes) {
    const Mesh mesh(test::cube_mesh(-1, 1));
    expect_watertight(mesh, {0, 0, 0}, 5, 2);
    // Axis-aligned rays (zero direction components) through the cube's vertices and edges.
    int hits = 0;
    for (double x : {-1.0, 0.0, 1.0}) {
        for (double y : {-1.0, 0.0, 1.0}) {
            Hit hit;
            for (const Ray& ray :
                 {Ray{{x, y, -5}, {0, 0, 1}}, Ray{{x, -5, y}, {0, 1, 0}}, Ray{{5, x, y}, {-1, 0, 0}}}) {
                ASSERT_TRUE(mesh.intersect(ray, kInf, hit)) << ray.origin;
                EXPECT_NEAR(hit.t, 4.0, 1e-12);
                ++hits;
            }
        }
    }
    EXPECT_EQ(hits, 27);
}

TEST(Bvh, MeshesAndSpheresTogetherGiveTheListsHits) {
    auto shapes = test::random_spheres(200, 21);
    shapes.push_back(std::make_unique<Mesh>(test::tessellated_sphere(3, 3.0, {1, 2, 3})));
    shapes.push_back(std::make_unique<Mesh>(test::cube_mesh(-4, -2)));
    shapes.push_back(std::make_unique<Plane>(Vec3{0, -12, 0}, Vec3{0, 1, 0}));
    const auto ptrs = pointers(shapes);
    const LinearAccelerator list(ptrs);
    const BvhAccelerator bvh(ptrs);
    expect_same_hits(list, bvh, rays_into(Bounds3{{-10, -10, -10}, {10, 10, 10}}, 3000, 4), ptrs);
}

TEST(Bvh, CoordinatesBeyondFloatRangeOrTinyStillHit) {
    // The nodes are float: boxes beyond float's range saturate outwards, tiny ones keep their digits.
    for (double scale : {1e-30, 1e40}) {
        std::vector<std::unique_ptr<Shape>> shapes;
        for (int i = 0; i < 20; ++i) {
            shapes.push_back(std::make_unique<Sphere>(Vec3{scale * (3 * i + 10), scale, 0}, scale));
        }
        const auto ptrs = pointers(shapes);
        const BvhAccelerator bvh(ptrs);
        for (int i = 0; i < 20; ++i) {
            Hit hit;
            const Ray ray{{scale * (3 * i + 10), 5 * scale, 0}, {0, -1, 0}};
            ASSERT_TRUE(bvh.intersect(ray, kInf, hit)) << scale << " " << i;
            EXPECT_EQ(hit.primitive, static_cast<std::uint32_t>(i));
            EXPECT_NEAR(hit.t, 3 * scale, 1e-12 * scale);
            EXPECT_TRUE(bvh.occluded(ray, kInf));
        }
    }
}

TEST(Bvh, ScalarTraversalGivesTheSameHitsAsAvx2) {
    auto shapes = test::random_spheres(500, 8);
    shapes.push_back(std::make_unique<Mesh>(test::tessellated_sphere(4, 3.0, {1, 2, 3})));
    const auto ptrs = pointers(shapes);
    const LinearAccelerator list(ptrs);
    const BvhAccelerator bvh(ptrs);
    WideBvh::force_scalar_traversal(true);
    EXPECT_FALSE(WideBvh::uses_avx2());
    expect_same_hits(list, bvh, rays_into(Bounds3{{-10, -10, -10}, {10, 10, 10}}, 2000, 6), ptrs);
    WideBvh::force_scalar_traversal(false);
    EXPECT_EQ(WideBvh::uses_avx2(), WideBvh::cpu_has_avx2());
    expect_same_hits(list, bvh, rays_into(Bounds3{{-10, -10, -10}, {10, 10, 10}}, 2000, 6), ptrs);
}

}  // namespace
}  // namespace glint
