// The wide BVH's build: the same tree whatever the thread count (its large ranges are binned and
// partitioned by several threads), and every primitive in exactly one leaf, inside its node's box.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cstring>
#include <random>

#include "glint/accel/wide_bvh.hpp"

namespace glint {
namespace {

// Small random boxes in a cube, enough of them that the top splits take the parallel path.
std::vector<Bounds3> random_boxes(std::size_t count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Bounds3> boxes(count);
    for (Bounds3& b : boxes) {
        const Vec3 c{100 * u(rng), 100 * u(rng), 100 * u(rng)};
        const Vec3 half{0.2 * u(rng), 0.2 * u(rng), 0.2 * u(rng)};
        b = {c - half, c + half};
    }
    return boxes;
}

WideBvh build_with_threads(std::span<const Bounds3> boxes, int threads) {
    WideBvh bvh;
    tbb::task_arena arena(threads);
    arena.execute([&] { bvh.build(boxes); });
    return bvh;
}

TEST(WideBvhBuild, IsTheSameTreeWithOneOrManyThreads) {
    const auto boxes = random_boxes(600000, 1);
    const WideBvh one = build_with_threads(boxes, 1);
    for (int threads : {2, 3}) {
        const WideBvh many = build_with_threads(boxes, threads);
        ASSERT_EQ(one.nodes().size(), many.nodes().size()) << threads;
        EXPECT_EQ(
            0, std::memcmp(one.nodes().data(), many.nodes().data(), one.nodes().size() * sizeof(WideBvhNode)))
            << threads;
        EXPECT_EQ(one.primitive_order(), many.primitive_order()) << threads;
    }
}

TEST(WideBvhBuild, EveryPrimitiveIsInOneLeafInsideItsBox) {
    const auto boxes = random_boxes(300000, 2);
    WideBvh bvh;
    bvh.build(boxes);
    const auto& order = bvh.primitive_order();
    std::vector<int> seen(boxes.size(), 0);
    for (const WideBvhNode& node : bvh.nodes()) {
        for (int c = 0; c < WideBvhNode::kWidth; ++c) {
            for (std::uint32_t i = node.child[c]; i < node.child[c] + node.count[c]; ++i) {
                const Bounds3& b = boxes[order[i]];
                ++seen[order[i]];
                EXPECT_TRUE(node.lo_x[c] <= b.lo.x && node.lo_y[c] <= b.lo.y && node.lo_z[c] <= b.lo.z &&
                            node.hi_x[c] >= b.hi.x && node.hi_y[c] >= b.hi.y && node.hi_z[c] >= b.hi.z)
                    << "primitive " << order[i];
            }
        }
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<std::ptrdiff_t>(boxes.size()));
    // The root's children cover everything.
    EXPECT_EQ(bvh.bounds().lo.x, std::min_element(boxes.begin(), boxes.end(), [](auto& a, auto& b) {
                                     return a.lo.x < b.lo.x;
                                 })->lo.x);
}

}  // namespace
}  // namespace glint
