// The BVH must give the hits the brute-force list gives: same primitive, same t, for thousands of rays,
// and no ray may slip through a closed mesh at a shared edge or vertex.
#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <chrono>
#include <fstream>

#include "accel/accel_test_scenes.hpp"
#include "glint/accel/bvh.hpp"
#include "glint/accel/linear.hpp"
#include "glint/geometry/box.hpp"
#include "glint/geometry/instance.hpp"
#include "glint/geometry/mesh_io/mesh_data.hpp"
#include "glint/geometry/plane.hpp"
#include "glint/geometry/rectangle.hpp"
#include "glint/geometry/triangle.hpp"
#include "test_data.hpp"

namespace glint {
namespace {

using test::expect_identical_hits;
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

// Small scenes skip the tree and test every shape; the answers must be the very same bits as the
// tree's, whichever shapes are mixed (inline spheres, virtual calls, planes kept apart).
TEST(Bvh, SmallScenesTestedFlatGiveTheTreesHitsBitForBit) {
    for (int scene = 0; scene < 3; ++scene) {
        auto shapes = test::random_spheres(12, 40 + scene);
        if (scene >= 1) {
            shapes.push_back(std::make_unique<Mesh>(test::tessellated_sphere(2, 2.0, {1, 2, 3})));
            shapes.push_back(std::make_unique<Rectangle>(Vec3{-5, -5, 4}, Vec3{10, 0, 0}, Vec3{0, 10, 0}));
        }
        if (scene == 2) {
            shapes.push_back(std::make_unique<Plane>(Vec3{0, -9, 0}, Vec3{0, 1, 0}));
        }
        const auto ptrs = pointers(shapes);
        const BvhAccelerator flat(ptrs, ptrs.size());
        const BvhAccelerator tree(ptrs, 0);
        EXPECT_EQ(flat.flat_count(), ptrs.size());
        EXPECT_EQ(tree.flat_count(), tree.unbounded_count());
        std::mt19937_64 rng(scene);
        int hits = 0;
        for (int i = 0; i < 4000; ++i) {
            // From anywhere in the cloud towards a point in the box of a random shape: most rays hit.
            const Bounds3 target = ptrs[rng() % (ptrs.size() - (scene == 2 ? 1 : 0))]->bounds();
            const Vec3 origin = random_in_box(rng, {-10, -10, -10}, {10, 10, 10});
            const Ray ray{origin, normalize(random_in_box(rng, target.lo, target.hi) - origin)};
            Hit a, b;
            const bool found = flat.intersect(ray, kInf, a);
            ASSERT_EQ(found, tree.intersect(ray, kInf, b));
            EXPECT_EQ(flat.occluded(ray, 5.0), tree.occluded(ray, 5.0));
            if (found) {
                ++hits;
                expect_identical_hits(a, b, dynamic_cast<const Mesh*>(ptrs[a.primitive]) != nullptr);
                EXPECT_TRUE(flat.occluded(ray, a.t * (1 + 1e-9)));
                EXPECT_FALSE(flat.occluded(ray, a.t * (1 - 1e-9)));
            }
        }
        EXPECT_GT(hits, 2000) << scene;  // the comparison means something only if rays hit
    }
    // The default: few shapes go flat, many to the tree.
    const auto few = test::random_spheres(static_cast<int>(BvhAccelerator::kFlatMaxShapes), 1);
    EXPECT_EQ(BvhAccelerator(pointers(few)).flat_count(), few.size());
    const auto many = test::random_spheres(static_cast<int>(BvhAccelerator::kFlatMaxShapes) + 1, 1);
    EXPECT_EQ(BvhAccelerator(pointers(many)).flat_count(), 0u);
}

// Spheres are tested four at a time with AVX2 when the CPU has it; the answers must be the very bits the
// one-at-a-time loop gives: the same t (so the same Hit), the first of exactly equal t's in list order,
// and other shapes (their own intersect) met in their place in the list. Lists of every length up to
// 14 (so every tail of a group of four), spheres overlapping, nested, duplicated, and met tangentially,
// rays from inside spheres and from on their surface, flat and in a tree (leaves of up to 4).
TEST(Bvh, SpheresFourAtATimeGiveTheOneAtATimeBits) {
    if (!WideBvh::cpu_has_avx2()) {
        GTEST_SKIP() << "no AVX2 on this CPU: only the one-at-a-time path exists";
    }
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> unit(0, 1);
    int hits = 0;
    int sphere_hits = 0;
    int other_hits = 0;
    int tangent_rays = 0;
    for (int scene = 0; scene < 120; ++scene) {
        const int count = 1 + scene % 14;
        std::vector<std::unique_ptr<Shape>> shapes;
        std::vector<std::pair<Vec3, double>> spheres;  // the spheres, for rays aimed at them
        for (int i = 0; i < count; ++i) {
            const double kind = unit(rng);
            if (scene % 3 != 0 && kind < 0.2) {  // a third of the scenes: spheres only
                const Vec3 corner = random_in_box(rng, {-2, -2, -2}, {2, 2, 2});
                shapes.push_back(std::make_unique<Rectangle>(corner, Vec3{1.5, 0, 0.3}, Vec3{0, 1.2, 0.4}));
            } else if (scene % 3 != 0 && kind < 0.25) {
                shapes.push_back(std::make_unique<Plane>(Vec3{0, -2.5, 0}, Vec3{0.1, 1, 0}));
            } else if (!spheres.empty() && kind < 0.4) {
                // The same sphere again (exact ties in t), or one nested in or touching a previous one.
                const auto [center, radius] = spheres[rng() % spheres.size()];
                const double r = kind < 0.3 ? radius : radius * (0.2 + 1.5 * unit(rng));
                spheres.emplace_back(kind < 0.35 ? center : center + Vec3{radius + r, 0, 0}, r);
                shapes.push_back(std::make_unique<Sphere>(spheres.back().first, spheres.back().second));
            } else {
                spheres.emplace_back(random_in_box(rng, {-2, -2, -2}, {2, 2, 2}), 0.1 + 1.2 * unit(rng));
                shapes.push_back(std::make_unique<Sphere>(spheres.back().first, spheres.back().second));
            }
        }
        const auto ptrs = pointers(shapes);
        for (const std::size_t flat_max : {ptrs.size(), std::size_t{0}}) {
            const BvhAccelerator bvh(ptrs, flat_max);
            for (int r = 0; r < 400; ++r) {
                Vec3 origin = random_in_box(rng, {-4, -4, -4}, {4, 4, 4});
                Vec3 direction = random_direction(rng);
                if (!spheres.empty() && r % 4 != 0) {
                    const auto [center, radius] = spheres[rng() % spheres.size()];
                    if (r % 4 == 1) {
                        // Tangent: past the centre at exactly one radius from it, perpendicular to the ray.
                        const Vec3 side = normalize(cross(direction, random_direction(rng)));
                        origin = center + radius * side - 3.0 * direction;
                        ++tangent_rays;
                    } else if (r % 4 == 2) {
                        // From inside, or from a point on the surface (t near 0).
                        origin = unit(rng) < 0.5 ? center + (0.9 * radius * unit(rng)) * random_direction(rng)
                                                 : center + radius * random_direction(rng);
                    } else {
                        // Towards the sphere, some just past its rim.
                        const Vec3 target = center + (1.1 * radius * unit(rng)) * random_direction(rng);
                        direction = normalize(target - origin);
                    }
                }
                const Ray ray{origin, direction};
                const double t_max = r % 5 == 0 ? 1 + 4 * unit(rng) : kInf;
                Hit scalar_hit, vector_hit;
                WideBvh::force_scalar_traversal(true);
                const bool scalar_found = bvh.intersect(ray, t_max, scalar_hit);
                const bool scalar_occluded = bvh.occluded(ray, t_max);
                WideBvh::force_scalar_traversal(false);
                const bool vector_found = bvh.intersect(ray, t_max, vector_hit);
                ASSERT_EQ(vector_found, scalar_found) << scene << " " << r;
                EXPECT_EQ(bvh.occluded(ray, t_max), scalar_occluded) << scene << " " << r;
                EXPECT_EQ(scalar_occluded, scalar_found);
                if (scalar_found) {
                    ++hits;
                    ++(dynamic_cast<const Sphere*>(ptrs[scalar_hit.primitive]) ? sphere_hits : other_hits);
                    expect_identical_hits(vector_hit, scalar_hit, false);
                }
            }
        }
    }
    WideBvh::force_scalar_traversal(false);
    // The comparison means something only if rays hit both kinds of shape, and tangents were tried.
    EXPECT_GT(sphere_hits, 40000);
    EXPECT_GT(other_hits, 2000);
    EXPECT_GT(tangent_rays, 15000);
    EXPECT_GT(hits, sphere_hits);

    // Exact ties: four copies of one sphere and a fifth; the first copy in list order is the one hit.
    std::vector<std::unique_ptr<Shape>> copies;
    for (int i = 0; i < 5; ++i) {
        copies.push_back(std::make_unique<Sphere>(Vec3{0, 0, 5}, 1.0));
    }
    const BvhAccelerator flat(pointers(copies));
    Hit hit;
    ASSERT_TRUE(flat.intersect(Ray{{0.1, 0.2, 0}, {0, 0, 1}}, kInf, hit));
    EXPECT_EQ(hit.primitive, 0u);

    // A tie across groups of four: a farther sphere first, then five copies of a nearer one. Entry 4
    // (the first lane of the second group) ties with entries 1 to 3 of the first, and the first of
    // them in list order, entry 1, is the one hit; entry 0's lane holds entry 4 then.
    std::vector<std::unique_ptr<Shape>> behind_and_copies;
    behind_and_copies.push_back(std::make_unique<Sphere>(Vec3{0, 0, 9}, 1.0));
    for (int i = 0; i < 5; ++i) {
        behind_and_copies.push_back(std::make_unique<Sphere>(Vec3{0, 0, 5}, 1.0));
    }
    const BvhAccelerator tied(pointers(behind_and_copies));
    ASSERT_EQ(tied.flat_count(), 6u);
    ASSERT_TRUE(tied.intersect(Ray{{0.1, 0.2, 0}, {0, 0, 1}}, kInf, hit));
    EXPECT_EQ(hit.primitive, 1u);
    ASSERT_TRUE(tied.intersect(Ray{{0.1, 0.2, 20}, {0, 0, -1}}, kInf, hit));
    EXPECT_EQ(hit.primitive, 0u);
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

// The bunny's stand-in that every clone has (accel_test_scenes.hpp): 81 920 triangles, closed, bumpy.
const MeshData& blob_data() {
    static const MeshData data = test::displaced_blob();
    return data;
}
const Mesh& blob() {
    static const Mesh mesh(blob_data());
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

// Rays that start on the surface, as shadow and bounce rays do: the any-hit traversal visits children
// in node order, not nearest first, and must still find an occluder whenever there is one.
void expect_brute_force_answers_from_the_surface(const Mesh& mesh) {
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

// The same rays, scaled with the mesh, hit the same triangles at the scaled t: nothing in the BVH or
// the triangle test depends on the size of the coordinates.
void expect_hits_independent_of_the_scale(const MeshData& original) {
    const Mesh unit(original);
    for (double scale : {0.1, 1000.0}) {
        MeshData scaled = original;
        for (Vec3& p : scaled.positions) {
            p *= scale;
        }
        const Mesh mesh(std::move(scaled));
        int hits = 0;
        for (const Ray& ray : rays_into(unit.bounds(), 500, 17)) {
            Hit a, b;
            const bool found = unit.intersect(ray, kInf, a);
            ASSERT_EQ(mesh.intersect({ray.origin * scale, ray.direction}, kInf, b), found);
            if (found) {
                ++hits;
                EXPECT_EQ(a.element, b.element);
                EXPECT_NEAR(a.t * scale, b.t, 1e-9 * b.t);
            }
        }
        EXPECT_GT(hits, 100);
    }
}

TEST(Bvh, GeneratedBlobIsLikeTheBunny) {
    const Mesh& mesh = blob();
    EXPECT_EQ(mesh.triangles().size(), 81920u);
    EXPECT_EQ(mesh.positions().size(), 40962u);  // shared: V = T / 2 + 2 for a closed genus-0 surface
    const Vec3 size = mesh.bounds().extent();
    EXPECT_GT(size.x, 0.1);
    EXPECT_LT(size.x, 0.25);
}

TEST(Bvh, GeneratedBlobGivesTheBruteForceHits) {
    EXPECT_GT(expect_brute_force_hits(blob(), rays_into(blob().bounds(), 150, 3)), 25);
}

TEST(Bvh, RaysLeavingTheGeneratedBlobsSurfaceGiveTheBruteForceAnswers) {
    expect_brute_force_answers_from_the_surface(blob());
}

// A scene of one mesh skips the flat list and goes straight to the mesh's own tree. It must give what
// the flat list gives: the same answers, to the bit, as the mesh beside a sphere that no ray meets
// (which keeps the flat list), with the scene index set. The records start with a stale index, as a
// path's reused Hit does.
TEST(Bvh, ALoneMeshGivesTheFlatListsAnswers) {
    const Mesh& mesh = blob();
    const Sphere far_away({1000, 1000, 1000}, 1);
    const Shape* lone[] = {&mesh};
    const Shape* listed[] = {&mesh, &far_away};
    const BvhAccelerator alone(lone), flat(listed);
    ASSERT_EQ(alone.flat_count(), 1u);
    ASSERT_EQ(flat.flat_count(), 2u);
    const auto surface = test::surface_rays(
        mesh.bounds(), 200, 29, [&](const Ray& ray, Hit& hit) { return mesh.intersect(ray, kInf, hit); });
    std::vector<Ray> rays = rays_into(mesh.bounds(), 300, 5);
    rays.insert(rays.end(), surface.bounce.begin(), surface.bounce.end());
    int hits = 0;
    for (const Ray& ray : rays) {
        Hit a, b;
        a.primitive = b.primitive = 7;
        const bool found = flat.intersect(ray, kInf, a);
        ASSERT_EQ(alone.intersect(ray, kInf, b), found);
        EXPECT_EQ(alone.occluded(ray, kInf), found);
        if (found) {
            ++hits;
            EXPECT_EQ(a.primitive, 0u);
            expect_identical_hits(a, b, true);
            EXPECT_FALSE(alone.occluded(ray, a.t * (1 - 1e-9)));
        }
    }
    EXPECT_GT(hits, 200);
    int occluded = 0;
    for (const Ray& shadow : surface.shadow) {
        const bool blocked = flat.occluded(shadow, 1.0);
        EXPECT_EQ(alone.occluded(shadow, 1.0), blocked);
        occluded += blocked ? 1 : 0;
    }
    EXPECT_GT(occluded, 20);
    EXPECT_GT(static_cast<int>(surface.shadow.size()) - occluded, 20);
}

TEST(Bvh, GeneratedBlobHitsDoNotDependOnTheScale) {
    expect_hits_independent_of_the_scale(blob_data());
}

// The same three on the Stanford bunny, when the optional data is there (test_data.hpp).
TEST(Bvh, BunnyMeshGivesTheBruteForceHits) {
    GLINT_REQUIRE_DATA_FILE(bunny_file, "meshes/stanford-bunny.obj");
    const Mesh& mesh = bunny(bunny_file);
    ASSERT_EQ(mesh.triangles().size(), 69451u);  // the file's header says 69451 faces
    EXPECT_GT(expect_brute_force_hits(mesh, rays_into(mesh.bounds(), 150, 3)), 25);
}

TEST(Bvh, RaysLeavingTheBunnysSurfaceGiveTheBruteForceAnswers) {
    GLINT_REQUIRE_DATA_FILE(bunny_file, "meshes/stanford-bunny.obj");
    expect_brute_force_answers_from_the_surface(bunny(bunny_file));
}

TEST(Bvh, BunnyHitsDoNotDependOnTheScale) {
    GLINT_REQUIRE_DATA_FILE(bunny_file, "meshes/stanford-bunny.obj");
    expect_hits_independent_of_the_scale(load_mesh_file(bunny_file));
}

// A mesh of over a million triangles: the BVH's hits are the brute force's. The brute force runs over
// every triangle for each ray, so the rays are few, and tested in parallel.
TEST(Bvh, AMillionTriangleMeshGivesTheBruteForceHits) {
#if defined(__SANITIZE_ADDRESS__)
    // Under AddressSanitizer a quarter of the size (262 144 triangles): the brute force is ~10x slower.
    constexpr std::uint32_t kAround = 512, kAcross = 256;
#else
    constexpr std::uint32_t kAround = 1024, kAcross = 512;  // 1 048 576 triangles
#endif
    const Mesh mesh(test::displaced_torus(kAround, kAcross));
    ASSERT_EQ(mesh.triangles().size(), 2u * kAround * kAcross);
    const std::vector<Ray> rays = rays_into(mesh.bounds(), 96, 41);
    struct Reference {
        bool found = false;
        TriangleHit hit;
        std::uint32_t element = 0;
    };
    std::vector<Reference> reference(rays.size());
    tbb::parallel_for(std::size_t{0}, rays.size(), [&](std::size_t i) {
        reference[i].found = brute_force(mesh, rays[i], reference[i].hit, reference[i].element);
    });
    int hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
        Hit hit;
        ASSERT_EQ(mesh.intersect(rays[i], kInf, hit), reference[i].found) << i;
        EXPECT_EQ(mesh.occluded(rays[i], kInf), reference[i].found) << i;
        if (reference[i].found) {
            ++hits;
            EXPECT_EQ(hit.element, reference[i].element);
            EXPECT_EQ(hit.t, reference[i].hit.t);
        }
    }
    EXPECT_GT(hits, 30);  // a torus: about half the rays aimed into its box hit it
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

// A shape tested by its own intersect (a box) and a rectangle on its face meet a ray at the very same t;
// the one first in the list is hit, whether the rectangles go four at a time (AVX2: the box is tested
// in its place among their lanes) or one at a time. Two more rectangles, out of the ray's way, make the
// list four at a time.
TEST(Bvh, AShapeTiedWithARectangleGoesByListOrder) {
    const Ray ray{{0.7, 1.3, 10}, {0, 0, -1}};
    for (const bool box_first : {true, false}) {
        std::vector<std::unique_ptr<Shape>> shapes;
        auto box = std::make_unique<Box>(Vec3{0, 0, 0}, Vec3{2, 2, 2});
        // The box's top face, z = 2, with the normal (0, 0, 1) exactly: both find t = 8 to the bit.
        auto face = std::make_unique<Rectangle>(Vec3{0, 0, 2}, Vec3{2, 0, 0}, Vec3{0, 2, 0});
        if (box_first) {
            shapes.push_back(std::move(box));
            shapes.push_back(std::move(face));
        } else {
            shapes.push_back(std::move(face));
            shapes.push_back(std::move(box));
        }
        shapes.push_back(std::make_unique<Rectangle>(Vec3{100, 0, 0}, Vec3{2, 0, 0}, Vec3{0, 2, 0}));
        shapes.push_back(std::make_unique<Rectangle>(Vec3{0, 100, 0}, Vec3{2, 0, 0}, Vec3{0, 2, 0}));
        const auto ptrs = pointers(shapes);
        const BvhAccelerator flat(ptrs, ptrs.size());
        ASSERT_EQ(flat.flat_count(), ptrs.size());
        for (const bool scalar : {true, false}) {
            WideBvh::force_scalar_traversal(scalar);
            Hit hit;
            ASSERT_TRUE(flat.intersect(ray, kInf, hit)) << box_first << scalar;
            EXPECT_EQ(hit.t, 8.0);
            EXPECT_EQ(hit.primitive, 0u) << "box first: " << box_first << ", scalar: " << scalar;
            EXPECT_TRUE(flat.occluded(ray, 9.0));
            EXPECT_FALSE(flat.occluded(ray, 8.0));
        }
        WideBvh::force_scalar_traversal(false);
    }
}

// The flat list tests its rectangles four at a time with AVX2 too (Rectangle::solve lane by lane); the
// answers must be the one-at-a-time loop's bits. A closed Cornell-like room (walls sharing their edges,
// so rays meet exact ties and hit edges and corners), a light just below the ceiling, rotated boxes
// (instances, tested by their own intersect in their place in the list), a sphere or two; rays from
// inside, from points on the walls, parallel to walls (a zero denominator), and aimed at edges.
TEST(Bvh, RectanglesFourAtATimeGiveTheOneAtATimeBits) {
    if (!WideBvh::cpu_has_avx2()) {
        GTEST_SKIP() << "no AVX2 on this CPU: only the one-at-a-time path exists";
    }
    std::mt19937_64 rng(555);
    std::uniform_real_distribution<double> unit(0, 1);
    const double s = 555;
    int rectangle_hits = 0;
    int other_hits = 0;
    for (int scene = 0; scene < 6; ++scene) {
        std::vector<std::unique_ptr<Shape>> shapes;
        shapes.push_back(std::make_unique<Rectangle>(Vec3{s, 0, 0}, Vec3{0, s, 0}, Vec3{0, 0, s}));
        shapes.push_back(std::make_unique<Rectangle>(Vec3{0, 0, 0}, Vec3{0, s, 0}, Vec3{0, 0, s}));
        shapes.push_back(std::make_unique<Rectangle>(Vec3{0, 0, 0}, Vec3{s, 0, 0}, Vec3{0, 0, s}));
        shapes.push_back(std::make_unique<Rectangle>(Vec3{s, s, s}, Vec3{-s, 0, 0}, Vec3{0, 0, -s}));
        shapes.push_back(std::make_unique<Rectangle>(Vec3{0, 0, s}, Vec3{s, 0, 0}, Vec3{0, s, 0}));
        if (scene % 2 == 0) {
            shapes.push_back(std::make_unique<Instance>(
                std::make_unique<Box>(Vec3{0, 0, 0}, Vec3{165, 330, 165}),
                Transform::rotate({0, 1, 0}, 15).then(Transform::translate({265, 0, 295}))));
        }
        if (scene >= 2) {
            shapes.push_back(std::make_unique<Sphere>(Vec3{150, 100, 150}, 60 + 10 * scene));
        }
        shapes.push_back(std::make_unique<Instance>(
            std::make_unique<Box>(Vec3{0, 0, 0}, Vec3{165, 165, 165}),
            Transform::rotate({0, 1, 0}, -18).then(Transform::translate({130, 0, 65}))));
        shapes.push_back(
            std::make_unique<Rectangle>(Vec3{343, 554, 332}, Vec3{-130, 0, 0}, Vec3{0, 0, -105}));
        if (scene >= 4) {
            // A duplicate of a wall: exact ties in t, which the first in list order wins.
            shapes.push_back(std::make_unique<Rectangle>(Vec3{0, 0, s}, Vec3{s, 0, 0}, Vec3{0, s, 0}));
        }
        const auto ptrs = pointers(shapes);
        const BvhAccelerator flat(ptrs, ptrs.size());
        ASSERT_EQ(flat.flat_count(), ptrs.size());
        for (int r = 0; r < 20000; ++r) {
            Vec3 origin = random_in_box(rng, {1, 1, 1}, {s - 1, s - 1, s - 1});
            Vec3 direction = random_direction(rng);
            switch (r % 5) {
                case 1:  // from a point on a wall, the floor or the ceiling
                    origin[static_cast<int>(rng() % 3)] = rng() % 2 == 0 ? 0.0 : s;
                    break;
                case 2:  // parallel to a wall
                    direction[static_cast<int>(rng() % 3)] = 0;
                    direction = normalize(direction);
                    break;
                case 3: {  // at an edge or corner of the room
                    Vec3 target{unit(rng) * s, unit(rng) * s, unit(rng) * s};
                    target[0] = rng() % 2 == 0 ? 0.0 : s;
                    target[1] = rng() % 2 == 0 ? 0.0 : s;
                    direction = normalize(target - origin);
                    break;
                }
                case 4:  // from outside the room
                    origin = random_in_box(rng, {-600, -600, -900}, {1200, 1200, 1200});
                    direction = normalize(random_in_box(rng, {0, 0, 0}, {s, s, s}) - origin);
                    break;
                default:
                    break;
            }
            const Ray ray{origin, direction};
            const double t_max = r % 7 == 0 ? 300 * unit(rng) : kInf;
            Hit scalar_hit, vector_hit;
            WideBvh::force_scalar_traversal(true);
            const bool scalar_found = flat.intersect(ray, t_max, scalar_hit);
            const bool scalar_occluded = flat.occluded(ray, t_max);
            WideBvh::force_scalar_traversal(false);
            const bool vector_found = flat.intersect(ray, t_max, vector_hit);
            ASSERT_EQ(vector_found, scalar_found) << scene << " " << r;
            EXPECT_EQ(flat.occluded(ray, t_max), scalar_occluded) << scene << " " << r;
            if (scalar_found) {
                ++(dynamic_cast<const Rectangle*>(ptrs[scalar_hit.primitive]) ? rectangle_hits : other_hits);
                expect_identical_hits(vector_hit, scalar_hit, false);
            }
        }
    }
    WideBvh::force_scalar_traversal(false);
    EXPECT_GT(rectangle_hits, 60000);
    EXPECT_GT(other_hits, 5000);
}

// The flat list skips a shape tested by a virtual call (an instanced box, a mesh) when the ray misses
// its box; that may only save time. Against the brute-force list, which tests every shape: the same
// hit, bit for bit, and the same occlusion, for rays aimed at the corners and edges of rotated boxes,
// along their faces' planes, from points on their faces and from inside them.
void expect_flat_box_tests_lose_no_hit(bool four_at_a_time) {
    const Transform tall_place = Transform::rotate({0, 1, 0}, 15).then(Transform::translate({265, 0, 295}));
    const Transform short_place = Transform::rotate({0, 1, 0}, -18).then(Transform::translate({130, 0, 65}));
    const Vec3 tall_size{165, 330, 165}, short_size{165, 165, 165};
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Rectangle>(Vec3{0, 0, 0}, Vec3{555, 0, 0}, Vec3{0, 0, 555}));
    shapes.push_back(std::make_unique<Instance>(std::make_unique<Box>(Vec3{}, tall_size), tall_place));
    shapes.push_back(std::make_unique<Instance>(std::make_unique<Box>(Vec3{}, short_size), short_place));
    shapes.push_back(std::make_unique<Mesh>(test::tessellated_sphere(2, 40.0, {400, 450, 150})));
    shapes.push_back(std::make_unique<Box>(Vec3{50, 400, 400}, Vec3{150, 500, 500}));  // axis-aligned
    if (four_at_a_time) {
        shapes.push_back(std::make_unique<Rectangle>(Vec3{0, 555, 0}, Vec3{555, 0, 0}, Vec3{0, 0, 555}));
        shapes.push_back(std::make_unique<Rectangle>(Vec3{0, 0, 555}, Vec3{555, 0, 0}, Vec3{0, 555, 0}));
    }
    const auto ptrs = pointers(shapes);
    const LinearAccelerator list(ptrs);
    const BvhAccelerator flat(ptrs);
    ASSERT_EQ(flat.flat_count(), ptrs.size());

    // Points of the boxes' surfaces (corners, edges, faces) and inside them, in world space.
    std::mt19937_64 rng(91);
    std::uniform_real_distribution<double> unit(0, 1);
    const auto box_point = [&](const Transform& place, const Vec3& size, int kind) {
        Vec3 local{unit(rng) * size.x, unit(rng) * size.y, unit(rng) * size.z};
        const int fixed = kind == 0 ? 3 : kind == 1 ? 2 : kind == 2 ? 1 : 0;  // corner, edge, face, inside
        for (int axis = 0; axis < fixed; ++axis) {
            local[axis] = rng() % 2 == 0 ? 0.0 : size[axis];
        }
        return place.point(local);
    };
    int hits = 0;
    for (int r = 0; r < 40000; ++r) {
        const bool tall = r % 2 == 0;
        const Vec3 target = box_point(tall ? tall_place : short_place, tall ? tall_size : short_size, r % 4);
        Vec3 origin = random_in_box(rng, {-100, -100, -100}, {650, 650, 650});
        Vec3 direction = normalize(target - origin);
        if (r % 5 == 1) {  // from the target itself, on or in a box, outwards in any direction
            origin = target;
            direction = random_direction(rng);
        } else if (r % 5 ==
                   2) {  // along an axis through the target: parallel to the axis-aligned box's faces
            direction = Vec3{};
            direction[static_cast<int>(rng() % 3)] = rng() % 2 == 0 ? 1.0 : -1.0;
            origin = target - 300 * direction;
        }
        const Ray ray{origin, direction};
        const double t_max = r % 7 == 0 ? 400 * unit(rng) : kInf;
        Hit a, b;
        const bool found = list.intersect(ray, t_max, a);
        ASSERT_EQ(flat.intersect(ray, t_max, b), found) << r;
        EXPECT_EQ(flat.occluded(ray, t_max), list.occluded(ray, t_max)) << r;
        if (found) {
            ++hits;
            expect_identical_hits(a, b, dynamic_cast<const Mesh*>(ptrs[a.primitive]) != nullptr);
        }
    }
    EXPECT_GT(hits, 20000);
}

// With two more rectangles the list has three, and its boxes are tested four at a time with AVX2
// (culling_box_lanes) instead of one at a time: both are checked (the second only on a CPU with AVX2,
// which the four-at-a-time path needs).
TEST(Bvh, TheFlatListsBoxTestsNeverLoseAHit) {
    expect_flat_box_tests_lose_no_hit(false);
    if (!WideBvh::uses_avx2()) {
        GTEST_SKIP() << "no AVX2 on this CPU: only the one-at-a-time box tests exist";
    }
    SCOPED_TRACE("four at a time");
    expect_flat_box_tests_lose_no_hit(true);
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

// Flat axis-aligned rectangles far from the origin and from the rays' origins: their boxes are padded
// slabs of zero thickness, whose near and far planes the node test crosses with separately rounded
// terms (the far ones grown inside the fused multiply-subtract, TraversalRay::inv_far); the padding
// must keep every such box the ray crosses. Rays nearly along the rectangles' normals, and along their
// planes, scalar and AVX2.
TEST(Bvh, FlatRectanglesFarAwayKeepEveryHit) {
    for (const double offset : {1e3, 1e6}) {
        std::vector<std::unique_ptr<Shape>> shapes;
        for (int k = 0; k < 60; ++k) {
            const double x = offset + 0.37 * k;
            const double y = -offset + 1.1 * (k % 7);
            const double z = 0.5 * offset + 0.9 * (k % 5);
            const Vec3 corner{x, y, z};
            switch (k % 3) {  // normal along x, y or z
                case 0:
                    shapes.push_back(std::make_unique<Rectangle>(corner, Vec3{0, 1, 0}, Vec3{0, 0, 1}));
                    break;
                case 1:
                    shapes.push_back(std::make_unique<Rectangle>(corner, Vec3{0, 0, 1}, Vec3{1, 0, 0}));
                    break;
                default:
                    shapes.push_back(std::make_unique<Rectangle>(corner, Vec3{1, 0, 0}, Vec3{0, 1, 0}));
                    break;
            }
        }
        const auto ptrs = pointers(shapes);
        const LinearAccelerator list(ptrs);
        const BvhAccelerator bvh(ptrs);
        ASSERT_EQ(bvh.flat_count(), 0u);  // all in the tree
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> unit(0, 1);
        std::vector<Ray> rays;
        for (int r = 0; r < 6000; ++r) {
            const auto& target = *static_cast<const Rectangle*>(ptrs[r % ptrs.size()]);
            // A point of the rectangle, and a ray to it from far away, nearly along its normal, or
            // from the side, nearly in its plane.
            const double a = unit(rng), b = unit(rng);
            Vec3 edge1, edge2;
            switch (r % ptrs.size() % 3) {
                case 0:
                    edge1 = {0, 1, 0};
                    edge2 = {0, 0, 1};
                    break;
                case 1:
                    edge1 = {0, 0, 1};
                    edge2 = {1, 0, 0};
                    break;
                default:
                    edge1 = {1, 0, 0};
                    edge2 = {0, 1, 0};
                    break;
            }
            const Vec3 on = target.corner() + a * edge1 + b * edge2;
            const Vec3 normal = cross(edge1, edge2);
            const Vec3 wobble{unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5};
            const Vec3 direction = r % 4 == 3 ? normalize(edge1 + 1e-3 * normal + 1e-3 * wobble)
                                              : normalize((r % 2 == 0 ? 1.0 : -1.0) * normal + 0.2 * wobble);
            const double distance = r % 8 == 0 ? 2 * offset : 30;
            rays.push_back({on - distance * direction, direction});
        }
        for (const bool scalar : {false, true}) {
            SCOPED_TRACE(scalar ? "scalar" : "avx2");
            WideBvh::force_scalar_traversal(scalar);
            expect_same_hits(list, bvh, rays, ptrs);
        }
        WideBvh::force_scalar_traversal(false);
    }
}

// Axis-aligned rays (a zero direction component: its inverse is a large stand-in) onto meshes and
// spheres far from the origin. Coordinate times stand-in overflowed float beyond 3.4e8, and the AVX2
// path (fused multiply-subtract) then culled boxes the ray was inside: these rays all missed.
TEST(Bvh, AxisAlignedRaysHitShapesFarFromTheOrigin) {
    for (const bool scalar : {false, true}) {
        WideBvh::force_scalar_traversal(scalar);
        for (double scale : {1.0, 1e9, 1e17, 1e25}) {
            const Vec3 center{-10 * scale, scale, 3 * scale};
            const Mesh mesh(test::tessellated_sphere(2, scale, center));
            std::vector<std::unique_ptr<Shape>> spheres;
            for (int i = 0; i < 20; ++i) {
                spheres.push_back(
                    std::make_unique<Sphere>(Vec3{scale * (3 * i + 10), scale, 3 * scale}, scale));
            }
            const auto ptrs = pointers(spheres);
            const BvhAccelerator bvh(ptrs);
            int rays = 0;
            for (const Vec3& vertex : mesh.positions()) {
                // Straight down through each vertex, and along x and z through it from outside.
                for (const Ray& ray : {Ray{vertex + Vec3{0, 5 * scale, 0}, {0, -1, 0}},
                                       Ray{vertex + Vec3{5 * scale, 0, 0}, {-1, 0, 0}},
                                       Ray{vertex - Vec3{0, 0, 5 * scale}, {0, 0, 1}}}) {
                    TriangleHit reference;
                    std::uint32_t element = 0;
                    ASSERT_TRUE(brute_force(mesh, ray, reference, element));
                    Hit hit;
                    ASSERT_TRUE(mesh.intersect(ray, kInf, hit))
                        << scale << " " << ray.origin << (scalar ? " scalar" : "");
                    // Through a vertex: the triangles around it give the same t up to rounding.
                    EXPECT_NEAR(hit.t, reference.t, 1e-14 * reference.t);
                    ++rays;
                }
            }
            EXPECT_EQ(rays, 3 * static_cast<int>(mesh.positions().size()));
            for (int i = 0; i < 20; ++i) {
                Hit hit;
                const Ray ray{{scale * (3 * i + 10), 5 * scale, 3 * scale}, {0, -1, 0}};
                ASSERT_TRUE(bvh.intersect(ray, kInf, hit)) << scale << " " << i << (scalar ? " scalar" : "");
                EXPECT_EQ(hit.primitive, static_cast<std::uint32_t>(i));
                EXPECT_NEAR(hit.t, 3 * scale, 1e-12 * scale);
            }
        }
    }
    WideBvh::force_scalar_traversal(false);
}

// ---- hostile coordinates: the build always ends, and the hits stay the brute force's -----------------

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A flat grid of triangles (z = 0) with one more triangle reaching out to x = 1e40, a finite double
// that float cannot hold. Its box saturates to infinity in float, and with the grid's zero thickness
// the SAH's area was inf · 0 = NaN: the build used to recurse until the stack overflowed.
TEST(Bvh, AMeshWithAVertexBeyondFloatRangeBuildsAndGivesTheBruteForceHits) {
    MeshData data;
    constexpr int kCells = 60;
    for (int j = 0; j <= kCells; ++j) {
        for (int i = 0; i <= kCells; ++i) {
            data.positions.push_back({static_cast<double>(i) / kCells, static_cast<double>(j) / kCells, 0});
        }
    }
    const auto at = [](int i, int j) { return static_cast<std::uint32_t>(j * (kCells + 1) + i); };
    for (int j = 0; j < kCells; ++j) {
        for (int i = 0; i < kCells; ++i) {
            data.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            data.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    data.positions.push_back({1e40, 0.5, 0});
    data.triangles.push_back(
        {at(kCells, 0), static_cast<std::uint32_t>(data.positions.size() - 1), at(kCells, kCells)});
    const auto start = std::chrono::steady_clock::now();
    const Mesh mesh(data);
    EXPECT_LT(seconds_since(start), 1.0);
    EXPECT_EQ(mesh.triangles().size(), 2u * kCells * kCells + 1);
    // Straight down onto the grid and beside it (x in [1, 1.5]: the far triangle, which is ~1e40 long).
    std::mt19937_64 rng(3);
    std::vector<Ray> rays;
    for (int i = 0; i < 300; ++i) {
        rays.push_back({random_in_box(rng, {-0.2, -0.2, 1}, {1.5, 1.2, 2}), {0, 0, -1}});
        rays.push_back({random_in_box(rng, {-0.2, -0.2, 1}, {1.5, 1.2, 2}), random_direction(rng)});
    }
    EXPECT_GT(expect_brute_force_hits(mesh, rays), 200);
    Hit hit;
    ASSERT_TRUE(mesh.intersect({{1e30, 0.5, 1}, {0, 0, -1}}, kInf, hit));  // far out on the long triangle
    EXPECT_EQ(hit.t, 1);
    const auto& far = mesh.triangles()[hit.element];
    EXPECT_TRUE(
        std::any_of(far.begin(), far.end(), [&](std::uint32_t v) { return mesh.positions()[v].x == 1e40; }));
}

// The most primitives in a leaf of the tree.
std::uint32_t largest_leaf(const WideBvh& bvh) {
    std::uint32_t largest = 0;
    for (const WideBvhNode& node : bvh.nodes()) {
        largest = std::max(largest, *std::max_element(node.count, node.count + WideBvhNode::kWidth));
    }
    return largest;
}

// Scene shapes beyond float's range among ordinary ones. A floor of flat tiles (y = 0), one of which
// reaches out to x = 1e40: the floor's box, infinite in x and of zero thickness, had the SAH area
// inf · 0 = NaN, and the build recursed until the stack overflowed. Spheres with a sphere at x = 1e40:
// every SAH cost was infinite, and all the shapes ended in one leaf, tested by every ray. The same with
// a sphere of radius 1e300 around everything. Each must build at once, sort the ordinary shapes into
// small leaves, and give the list's hits.
TEST(Bvh, ShapesBeyondFloatRangeAmongOthersGiveTheListsHits) {
    for (const std::string scene : {"floor", "far sphere", "far and huge spheres"}) {
        std::vector<std::unique_ptr<Shape>> shapes;
        std::uint32_t far_shape = 0;  // the index of the shape at 1e40
        if (scene == "floor") {
            for (int i = 0; i < 24; ++i) {
                shapes.push_back(std::make_unique<Rectangle>(
                    Vec3{-10.0 + 5 * (i % 4), 0, -10.0 + 3 * (i / 4)}, Vec3{0, 0, 2}, Vec3{4, 0, 0}));
            }
            far_shape = static_cast<std::uint32_t>(shapes.size());
            shapes.push_back(std::make_unique<Rectangle>(Vec3{10, 0, -1}, Vec3{0, 0, 2}, Vec3{1e40, 0, 0}));
        } else {
            shapes = test::random_spheres(300, 13);
            far_shape = static_cast<std::uint32_t>(shapes.size());
            shapes.push_back(std::make_unique<Sphere>(Vec3{1e40, 0, 0}, 1));
            if (scene == "far and huge spheres") {
                shapes.push_back(std::make_unique<Sphere>(Vec3{0, 0, 0}, 1e300));
            }
        }
        const auto ptrs = pointers(shapes);
        const auto start = std::chrono::steady_clock::now();
        const BvhAccelerator bvh(ptrs);
        EXPECT_LT(seconds_since(start), 1.0) << scene;
        EXPECT_LE(largest_leaf(bvh.bvh()), 4u) << scene;  // BvhBuildOptions::max_leaf_size
        const LinearAccelerator list(ptrs);
        expect_same_hits(list, bvh, rays_into(Bounds3{{-10, -1, -10}, {10, 1, 10}}, 2000, 14), ptrs);
        // The far shape, from beside it, far out.
        Hit hit;
        const double far_x = scene == "floor" ? 5e39 : 1e40;
        ASSERT_TRUE(bvh.intersect({{far_x, 5, 0}, {0, -1, 0}}, 1e20, hit)) << scene;
        EXPECT_EQ(hit.primitive, far_shape) << scene;
        EXPECT_EQ(hit.t, scene == "floor" ? 5 : 4) << scene;
    }
}

// The BVH works in float: a mesh file must not hold a coordinate float cannot, and says where it is.
TEST(Bvh, AMeshFileWithACoordinateBeyondFloatRangeIsAPositionedError) {
    const auto path = std::filesystem::path(testing::TempDir()) / "far.obj";
    std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 0 1e40 0\nf 1 2 3\n";
    const auto start = std::chrono::steady_clock::now();
    try {
        load_mesh_file(path);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_LT(seconds_since(start), 1.0);
        EXPECT_EQ(e.position().line, 3);
        EXPECT_EQ(e.position().column, 5);
        EXPECT_NE(std::string(e.what()).find("beyond float's range"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace glint
