// Accelerator::intersect_packet must give every ray the hit its own intersect gives, bit for bit: the
// BVH's packets of camera rays walk the tree once for all of them, in an order that is not each ray's,
// so ties between spheres at the same t are where a ray's answer could come to depend on the rays
// beside it. Packets of every size, coherent and not, with ties, beyond float's range, and scenes the
// packets do not take.
#include <gtest/gtest.h>

#include <random>

#include "accel/accel_test_scenes.hpp"
#include "glint/accel/bvh.hpp"
#include "glint/accel/linear.hpp"
#include "glint/geometry/plane.hpp"
#include "glint/geometry/sphere.hpp"

namespace glint {
namespace {

using test::expect_identical_hits;
using test::pointers;
using test::random_direction;
using test::random_in_box;

bool same_place(const Vec3& a, const Vec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

// Traces `rays` as one packet (or several, beyond WideBvh::kMaxPacket) and each ray alone; every field
// of the two hits must be the same bits. Returns how many rays hit.
int expect_packet_gives_each_rays_hit(const Accelerator& accel, const std::vector<Ray>& rays) {
    const int n = static_cast<int>(rays.size());
    std::vector<Hit> together(rays.size());
    std::vector<const Ray*> ray_pointers;
    std::vector<Hit*> hit_pointers;
    for (int k = 0; k < n; ++k) {
        ray_pointers.push_back(&rays[static_cast<std::size_t>(k)]);
        hit_pointers.push_back(&together[static_cast<std::size_t>(k)]);
    }
    std::unique_ptr<bool[]> found(new bool[rays.size() + 1]);
    accel.intersect_packet(ray_pointers.data(), n, kInf, hit_pointers.data(), found.get());
    int hits = 0;
    for (int k = 0; k < n; ++k) {
        const auto i = static_cast<std::size_t>(k);
        Hit alone;
        const bool found_alone = accel.intersect(rays[i], kInf, alone);
        EXPECT_EQ(found[i], found_alone) << "ray " << k << " of " << n;
        if (!found_alone || !found[i]) {
            continue;
        }
        ++hits;
        // `element` too: both records started as Hit{}, and only a mesh writes it.
        expect_identical_hits(together[i], alone, true);
    }
    return hits;
}

// `count` rays from around `eye` into a cone about `towards`: a pixel's camera rays through a lens.
std::vector<Ray> camera_like(std::mt19937_64& rng, const Vec3& eye, const Vec3& towards, double spread,
                             int count) {
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Ray> rays;
    for (int k = 0; k < count; ++k) {
        const Vec3 origin = eye + 0.05 * Vec3{u(rng), u(rng), u(rng)};
        rays.push_back({origin, towards + spread * Vec3{u(rng), u(rng), u(rng)}});
    }
    return rays;
}

TEST(Packet, CameraRaysOfATreeOfSpheresGetTheirOwnHitsBitForBit) {
    const auto shapes = test::random_spheres(1500, 21);
    const auto ptrs = pointers(shapes);
    const BvhAccelerator bvh(ptrs);
    ASSERT_GT(bvh.bvh().nodes().size(), 1u);  // a tree, which the packets take
    std::mt19937_64 rng(3);
    int hits = 0;
    int rays = 0;
    for (int p = 0; p < 400; ++p) {
        const Vec3 eye = random_in_box(rng, {-14, -14, -14}, {14, 14, 14});
        const Vec3 towards = random_in_box(rng, {-3, -3, -3}, {3, 3, 3}) - eye;
        // Every packet size, and spreads from a pixel's to rays that share little but their origin.
        const int count = 1 + p % WideBvh::kMaxPacket;
        const double spread = p % 3 == 0 ? 0.002 : p % 3 == 1 ? 0.05 : 1.0;
        const std::vector<Ray> packet = camera_like(rng, eye, towards, spread * length(towards), count);
        hits += expect_packet_gives_each_rays_hit(bvh, packet);
        rays += count;
    }
    EXPECT_GT(hits, rays / 4);
    // Rays that start inside the cloud, in every direction: no two alike.
    for (int p = 0; p < 100; ++p) {
        std::vector<Ray> packet;
        for (int k = 0; k < WideBvh::kMaxPacket; ++k) {
            packet.push_back({random_in_box(rng, {-9, -9, -9}, {9, 9, 9}), random_direction(rng)});
        }
        expect_packet_gives_each_rays_hit(bvh, packet);
    }
}

// Spheres in pairs at the very same place: every ray that hits one meets the other at the same t, a
// tie that a ray alone settles by the order it visits them. The packet settles it the same way.
TEST(Packet, TiesBetweenSpheresGoAsForTheRayAlone) {
    std::vector<std::unique_ptr<Shape>> shapes;
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> radius(0.2, 1.0);
    for (int i = 0; i < 300; ++i) {
        const Vec3 center = random_in_box(rng, {-10, -10, -10}, {10, 10, 10});
        const double r = radius(rng);
        shapes.push_back(std::make_unique<Sphere>(center, r));
        if (i % 2 == 0) {
            shapes.push_back(std::make_unique<Sphere>(center, r));  // its twin
        }
    }
    const auto ptrs = pointers(shapes);
    const BvhAccelerator bvh(ptrs);
    int tied = 0;
    for (int p = 0; p < 300; ++p) {
        const Vec3 eye = random_in_box(rng, {-14, -14, -14}, {14, 14, 14});
        const Vec3 towards = random_in_box(rng, {-2, -2, -2}, {2, 2, 2}) - eye;
        const std::vector<Ray> packet =
            camera_like(rng, eye, towards, (p % 2 == 0 ? 0.01 : 0.3) * length(towards), WideBvh::kMaxPacket);
        expect_packet_gives_each_rays_hit(bvh, packet);
        for (const Ray& ray : packet) {
            Hit hit;
            if (bvh.intersect(ray, kInf, hit)) {
                const auto* sphere = static_cast<const Sphere*>(ptrs[hit.primitive]);
                for (const Shape* other : ptrs) {
                    const auto* twin = static_cast<const Sphere*>(other);
                    if (twin != sphere && same_place(twin->center(), sphere->center())) {
                        ++tied;  // a hit on a sphere with a twin: a tie
                        break;
                    }
                }
            }
        }
    }
    EXPECT_GT(tied, 1000);  // the test means something only if ties happen
}

// Ties across leaves: a unit sphere resting on a ground sphere of radius 1000, and rays along the axis
// through the point where they touch, from inside either one: both roots are exactly t = 1 (3 / 3 and
// 1999 / 1999, or 2 / 2 and 2001 / 2001). A ray alone takes the one whose box it is inside, which it
// visits first (the other box it enters only near t = 1). In a packet, other rays that start inside the
// other box make both boxes' nearest entry 0, and the packet's order between them is then fixed by the
// tree, the same for both rays: for one of the two it is not the ray's own.
TEST(Packet, TiesAcrossLeavesGoAsForTheRayAlone) {
    std::vector<std::unique_ptr<Shape>> shapes;
    shapes.push_back(std::make_unique<Sphere>(Vec3{0, 1, 0}, 1.0));
    shapes.push_back(std::make_unique<Sphere>(Vec3{0, -1000, 0}, 1000.0));
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(3, 20);
    for (int i = 0; i < 300; ++i) {
        // Small spheres around, off the axis, so that the tree has many leaves.
        const double x = (i % 2 == 0 ? 1 : -1) * u(rng);
        const double z = (i % 4 < 2 ? 1 : -1) * u(rng);
        shapes.push_back(std::make_unique<Sphere>(Vec3{x, 0.5 + 0.02 * (i % 100), z}, 0.5));
    }
    const auto ptrs = pointers(shapes);
    const BvhAccelerator bvh(ptrs);
    ASSERT_EQ(bvh.flat_count(), 0u);
    const Ray down{{0, 1, 0}, {0, -1, 0}};  // from inside the small sphere: takes it alone
    const Ray up{{0, -1, 0}, {0, 1, 0}};    // from inside the ground: takes the ground alone
    Hit hit;
    ASSERT_TRUE(bvh.intersect(down, kInf, hit));
    EXPECT_EQ(hit.t, 1.0);
    EXPECT_EQ(hit.primitive, 0u);
    ASSERT_TRUE(bvh.intersect(up, kInf, hit));
    EXPECT_EQ(hit.t, 1.0);
    EXPECT_EQ(hit.primitive, 1u);
    for (int p = 0; p < 60; ++p) {
        for (const bool going_down : {true, false}) {
            // The axis ray among rays that start inside the other sphere's box, in every position.
            std::vector<Ray> packet;
            const int count = 2 + p % (WideBvh::kMaxPacket - 1);
            for (int k = 0; k < count; ++k) {
                const Vec3 inside_other = going_down ? random_in_box(rng, {-30, -30, -30}, {30, -0.1, 30})
                                                     : random_in_box(rng, {-0.9, 0.1, -0.9}, {0.9, 1.9, 0.9});
                packet.push_back(k == p % count ? (going_down ? down : up)
                                                : Ray{inside_other, random_direction(rng)});
            }
            expect_packet_gives_each_rays_hit(bvh, packet);
        }
    }
}

TEST(Packet, RaysBeyondFloatsRangeLargePacketsAndTheScalarTraversal) {
    const auto shapes = test::random_spheres(800, 4);
    const auto ptrs = pointers(shapes);
    const BvhAccelerator bvh(ptrs);
    EXPECT_EQ(bvh.traces_packets(), WideBvh::uses_avx2());  // a tree of spheres alone
    std::mt19937_64 rng(12);
    // A ray from beyond float's range among ordinary ones: the packet is traced ray by ray.
    std::vector<Ray> packet = camera_like(rng, {0, 0, -20}, {0, 0, 1}, 0.3, 8);
    packet.push_back({{0, 0, -1e31}, {0, 0.001, 1}});
    packet.push_back({{0.1, 0.2, 1e35}, {0, 0, -1}});
    EXPECT_GT(expect_packet_gives_each_rays_hit(bvh, packet), 0);
    // More rays than a packet holds: several packets.
    EXPECT_GT(expect_packet_gives_each_rays_hit(bvh, camera_like(rng, {0, 0, -20}, {0, 0, 1}, 0.3, 40)), 0);
    // None at all.
    EXPECT_EQ(expect_packet_gives_each_rays_hit(bvh, {}), 0);
    // Without AVX2 (forced), the rays go one at a time.
    WideBvh::force_scalar_traversal(true);
    EXPECT_FALSE(bvh.traces_packets());
    EXPECT_GT(expect_packet_gives_each_rays_hit(bvh, camera_like(rng, {0, 0, -20}, {0, 0, 1}, 0.3, 16)), 0);
    WideBvh::force_scalar_traversal(false);
}

// Scenes whose packets go ray by ray (a plane outside the tree, a mesh in it, a flat list of a few
// spheres) and the other accelerators: intersect_packet is each ray's intersect all the same.
TEST(Packet, OtherScenesAndAcceleratorsGiveEachRaysHit) {
    std::mt19937_64 rng(6);
    // Packets from all around towards `target`.
    const auto check = [&](const Accelerator& accel, const Vec3& target) {
        EXPECT_FALSE(accel.traces_packets());  // so the path tracer gathers no bounces for them
        int hits = 0;
        for (int p = 0; p < 50; ++p) {
            const Vec3 eye = random_in_box(rng, {-14, -14, -14}, {14, 14, 14});
            hits += expect_packet_gives_each_rays_hit(
                accel, camera_like(rng, eye, target - eye, 0.02 * length(target - eye), WideBvh::kMaxPacket));
        }
        EXPECT_GT(hits, 0);
    };
    {
        auto shapes = test::random_spheres(300, 9);
        shapes.push_back(std::make_unique<Plane>(Vec3{0, -5, 0}, Vec3{0, 1, 0}));
        const auto ptrs = pointers(shapes);
        check(BvhAccelerator(ptrs), {0, -5, 0});
        check(LinearAccelerator(ptrs), {0, -5, 0});
    }
    {
        auto shapes = test::random_spheres(300, 10);
        shapes.push_back(std::make_unique<Mesh>(test::tessellated_sphere(3, 3.0, {1, 2, 3})));
        const auto ptrs = pointers(shapes);
        check(BvhAccelerator(ptrs), {1, 2, 3});
    }
    {
        const auto shapes = test::random_spheres(5, 11);
        const auto ptrs = pointers(shapes);
        check(BvhAccelerator(ptrs), static_cast<const Sphere*>(ptrs[0])->center());
    }
}

}  // namespace
}  // namespace glint
