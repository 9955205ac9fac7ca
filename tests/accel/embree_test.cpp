// Embree and the BVH must agree ray for ray (built only when Embree is).
#ifdef GLINT_HAVE_EMBREE

#include <gtest/gtest.h>

#include <string>

#include "accel/accel_test_scenes.hpp"
#include "glint/accel/bvh.hpp"
#include "glint/accel/embree.hpp"
#include "glint/accel/linear.hpp"
#include "glint/bvh/wide_bvh.hpp"
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

// A mesh (the bunny or its stand-in), a small tessellated sphere beside it and a sphere: Embree's hits
// are the BVH's.
void expect_bvhs_hits_with(MeshData data, const std::string& device_config = "") {
    const Bounds3 box = Mesh(data).bounds();
    const Vec3 size = box.extent();
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Mesh>(std::move(data)));
    shapes.push_back(
        std::make_unique<Mesh>(test::tessellated_sphere(4, 0.2 * size.x, box.hi - Vec3{0, 0.1 * size.y, 0})));
    shapes.push_back(std::make_unique<Sphere>(box.lo + Vec3{0, 0.7 * size.y, 0}, 0.13 * size.x));
    const auto ptrs = pointers(shapes);
    const BvhAccelerator bvh(ptrs);
    const EmbreeAccelerator embree(ptrs, device_config);
    expect_same_hits(bvh, embree, rays_into(bvh.bounds(), 3000, 13), ptrs, {true, 1e-5});
}

// Rays leaving a surface: Embree's float test can find the triangle a ray starts on, which the
// backend's double-precision filter must reject (else: false shadows and hits at t ≈ 0).
void expect_bvhs_answers_from_the_surface(MeshData data) {
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Mesh>(std::move(data)));
    const auto ptrs = pointers(shapes);
    const BvhAccelerator bvh(ptrs);
    const EmbreeAccelerator embree(ptrs);
    const auto rays = test::surface_rays(
        bvh.bounds(), 20000, 29, [&](const Ray& ray, Hit& hit) { return bvh.intersect(ray, kInf, hit); });
    int differ = 0, occluded = 0;
    for (const Ray& shadow : rays.shadow) {
        const bool blocked = bvh.occluded(shadow, 1.0);
        differ += blocked != embree.occluded(shadow, 1.0) ? 1 : 0;
        occluded += blocked ? 1 : 0;
    }
    EXPECT_EQ(differ, 0) << "of " << rays.shadow.size() << " shadow rays";
    // Both answers are common, so the comparison means something.
    EXPECT_GT(occluded, 1000);
    EXPECT_GT(static_cast<int>(rays.shadow.size()) - occluded, 1000);
    // A bounce ray that grazes a triangle next to its start, close to that triangle's edge, may be
    // missed: Embree's float test puts the hit on the neighbour across the edge, which the double filter
    // rightly rejects, and never reports the triangle the double test hits. Such rays (incidence within
    // 6° of grazing) are allowed to differ, one in a thousand at most; any other must agree.
    int grazing_misses = 0;
    for (const Ray& bounce : rays.bounce) {
        Hit a, b;
        const bool found = bvh.intersect(bounce, kInf, a);
        const bool embree_found = embree.intersect(bounce, kInf, b);
        if (found && std::abs(dot(normalize(bounce.direction), a.normal)) < 0.1 &&
            (!embree_found || std::abs(a.t - b.t) > 1e-12 * a.t)) {
            ++grazing_misses;
            continue;
        }
        ASSERT_EQ(embree_found, found) << bounce.origin << " + t " << bounce.direction;
        if (found) {
            EXPECT_NEAR(a.t, b.t, 1e-12 * a.t);
        }
    }
    EXPECT_LE(grazing_misses, static_cast<int>(rays.bounce.size()) / 1000);
}

TEST(Embree, GeneratedBlobAndMeshesGiveTheBvhsHits) {
    expect_bvhs_hits_with(test::displaced_blob());
}

// A device given a configuration answers as the default one does (bench/accel.cpp holds Embree to AVX2
// so, on CPUs where it would otherwise run its AVX-512 kernels).
TEST(Embree, ADeviceHeldToAvx2GivesTheBvhsHits) {
    expect_bvhs_hits_with(test::displaced_blob(), "isa=avx2");
}

// The configuration reaches Embree: asked to say what it builds (verbose=2), a device held to AVX2
// names only AVX2 kernels (Embree prints to standard output).
TEST(Embree, TheDeviceConfigurationReachesEmbree) {
    if (!WideBvh::cpu_has_avx2()) {
        GTEST_SKIP() << "no AVX2 on this CPU";
    }
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Mesh>(test::tessellated_sphere(2)));
    const auto ptrs = pointers(shapes);
    ::testing::internal::CaptureStdout();
    {
        const EmbreeAccelerator embree(ptrs, "isa=avx2,verbose=2");
        Hit hit;
        EXPECT_TRUE(embree.intersect(Ray{{0, 0, -5}, {0, 0, 1}}, kInf, hit));
    }
    const std::string said = ::testing::internal::GetCapturedStdout();
    EXPECT_NE(said.find("avx2::"), std::string::npos) << said;
    EXPECT_EQ(said.find("avx512::"), std::string::npos) << said;
}

TEST(Embree, RaysLeavingTheGeneratedBlobsSurfaceGiveTheBvhsAnswers) {
    expect_bvhs_answers_from_the_surface(test::displaced_blob());
}

// The same two on the Stanford bunny, when the optional data is there (test_data.hpp).
TEST(Embree, BunnyAndMeshesGiveTheBvhsHits) {
    GLINT_REQUIRE_DATA_FILE(bunny_file, "meshes/stanford-bunny.obj");
    expect_bvhs_hits_with(load_mesh_file(bunny_file));
}

TEST(Embree, RaysLeavingTheBunnysSurfaceGiveTheBvhsAnswers) {
    GLINT_REQUIRE_DATA_FILE(bunny_file, "meshes/stanford-bunny.obj");
    expect_bvhs_answers_from_the_surface(load_mesh_file(bunny_file));
}

// Two independent accelerators over a mesh of over a million triangles (the BVH's own test against the
// brute force can afford only a few rays at this size).
TEST(Embree, AMillionTriangleMeshGivesTheBvhsHits) {
#if defined(__SANITIZE_ADDRESS__)
    constexpr std::uint32_t kAround = 512, kAcross = 256;  // 262 144 triangles: ASan is ~10x slower
#else
    constexpr std::uint32_t kAround = 1024, kAcross = 512;  // 1 048 576 triangles
#endif
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Mesh>(test::displaced_torus(kAround, kAcross)));
    const auto ptrs = pointers(shapes);
    const BvhAccelerator bvh(ptrs);
    const EmbreeAccelerator embree(ptrs);
    expect_same_hits(bvh, embree, rays_into(bvh.bounds(), 3000, 43), ptrs, {true, 1e-5});
}

// Embree leaves out any primitive with a coordinate beyond 1.844e18; the backend tests such shapes
// itself, so they are still hit, as the list hits them.
TEST(Embree, ShapesBeyondEmbreesRangeAreStillHit) {
    for (double scale : {1e17, 1e19, 1e40}) {
        std::vector<std::unique_ptr<Shape>> shapes;
        for (int i = 0; i < 20; ++i) {
            shapes.push_back(std::make_unique<Sphere>(Vec3{scale * (3 * i + 10), scale, 0}, scale));
        }
        MeshData far_mesh = test::tessellated_sphere(2, scale, {-10 * scale, scale, 0});
        shapes.push_back(std::make_unique<Mesh>(std::move(far_mesh)));
        const auto ptrs = pointers(shapes);
        const LinearAccelerator list(ptrs);
        const EmbreeAccelerator embree(ptrs);
        for (int i = 0; i <= 20; ++i) {
            // Down onto the top of each sphere; onto the mesh beside its top vertex (a ray exactly
            // through a vertex or an edge can be lost by this backend: Embree's float test and the
            // double filter may each give the hit to a different triangle around it).
            const Vec3 origin = i < 20 ? Vec3{scale * (3 * i + 10), 5 * scale, 0}
                                       : Vec3{-9.7 * scale, 5 * scale, 0.2 * scale};
            const Ray ray{origin, {0, -1, 0}};
            Hit expected, hit;
            ASSERT_TRUE(list.intersect(ray, kInf, expected)) << scale << " " << i;
            ASSERT_TRUE(embree.intersect(ray, kInf, hit)) << scale << " " << i;
            EXPECT_EQ(hit.primitive, static_cast<std::uint32_t>(i));
            EXPECT_NEAR(hit.t, expected.t, 1e-12 * expected.t);
            EXPECT_LT(hit.t, 3.2 * scale);  // the top, not the bottom
            EXPECT_TRUE(embree.occluded(ray, kInf));
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
