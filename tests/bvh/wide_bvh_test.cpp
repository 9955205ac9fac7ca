// The wide BVH's build: the same tree whatever the thread count (its large ranges are binned and
// partitioned by several threads), and every primitive in exactly one leaf, inside its node's box.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <random>
#include <string>

#include "glint/bvh/wide_bvh.hpp"

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

// The deepest leaf, in wide levels, below node `index`.
int depth_below(const WideBvh& bvh, std::uint32_t index) {
    int deepest = 0;
    const WideBvhNode& node = bvh.nodes()[index];
    for (int c = 0; c < WideBvhNode::kWidth; ++c) {
        if (node.count[c] == 0 && node.child[c] != 0) {
            deepest = std::max(deepest, depth_below(bvh, node.child[c]));
        }
    }
    return deepest + 1;
}

// Whatever the boxes (NaN, infinite, all equal, beyond float's range, flat and infinitely long, spread
// over 38 orders of magnitude), the build ends within a second with a tree no deeper than kMaxDepth
// that holds every primitive exactly once, inside its node's box. Some of these recursed for ever.
TEST(WideBvhBuild, AnyBoxesGiveATreeOfBoundedDepthHoldingEveryPrimitiveOnce) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::map<std::string, std::vector<Bounds3>> cases;
    cases["all equal"] = std::vector<Bounds3>(20000, Bounds3{{1, 2, 3}, {4, 5, 6}});
    cases["equal points"] = std::vector<Bounds3>(5000, Bounds3{{1, 1, 1}, {1, 1, 1}});
    for (const Bounds3& b : random_boxes(3000, 4)) {
        cases["1e40 and flat"].push_back({{b.lo.x, b.lo.y, 0}, {b.hi.x, b.hi.y, 0}});
        cases["1e40 and flat"].push_back({{b.lo.x, b.lo.y, 0}, {1e40, b.hi.y, 0}});
        cases["NaN"].push_back(b);
        cases["NaN"].push_back({{nan, b.lo.y, b.lo.z}, {b.hi.x, nan, b.hi.z}});
        cases["infinite"].push_back(b);
        cases["infinite"].push_back(Bounds3::infinite());
        cases["1e300"].push_back({b.lo * 1e298, b.hi * 1e298});
    }
    for (int i = 0; i < 3000; ++i) {
        // Points at x = 1.03^i, up to 1e38: each SAH split peels off the farthest few.
        const Vec3 p{std::pow(1.03, i), 0, 0};
        cases["exponential"].push_back({p, p});
    }
    for (const auto& [name, boxes] : cases) {
        WideBvh bvh;
        const auto start = std::chrono::steady_clock::now();
        bvh.build(boxes);
        EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0)
            << name;
        ASSERT_FALSE(bvh.nodes().empty()) << name;
        EXPECT_LE(depth_below(bvh, 0), WideBvh::kMaxDepth) << name;
        const auto& order = bvh.primitive_order();
        std::vector<int> seen(boxes.size(), 0);
        for (const WideBvhNode& node : bvh.nodes()) {
            for (int c = 0; c < WideBvhNode::kWidth; ++c) {
                for (std::uint32_t i = node.child[c]; i < node.child[c] + node.count[c]; ++i) {
                    const Bounds3& b = boxes[order[i]];
                    ++seen[order[i]];
                    // A NaN bound is unknown: the node's box must then be infinite on that side.
                    const auto below = [](float lo, double x) {
                        return std::isnan(x) ? std::isinf(lo) : lo <= x;
                    };
                    const auto above = [](float hi, double x) {
                        return std::isnan(x) ? std::isinf(hi) : hi >= x;
                    };
                    EXPECT_TRUE(below(node.lo_x[c], b.lo.x) && below(node.lo_y[c], b.lo.y) &&
                                below(node.lo_z[c], b.lo.z) && above(node.hi_x[c], b.hi.x) &&
                                above(node.hi_y[c], b.hi.y) && above(node.hi_z[c], b.hi.z))
                        << name << ": primitive " << order[i];
                }
            }
        }
        EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<std::ptrdiff_t>(boxes.size())) << name;
    }
}

// The exponential points force the median splits below kMedianSplitDepth; the tree still answers
// every ray like a test of every point would: a ray along +x from the origin meets all of them.
TEST(WideBvhBuild, MedianSplitsStillFindEveryPrimitive) {
    std::vector<Bounds3> boxes;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 p{std::pow(1.03, i), 0, 0};
        boxes.push_back({p - Vec3{0, 1, 1}, p + Vec3{0, 1, 1}});
    }
    WideBvh bvh;
    bvh.build(boxes);
    std::vector<int> visited(boxes.size(), 0);
    bvh.occluded(Ray{{0, 0, 0}, {1, 0, 0}}, kInf,
                 [&](std::uint32_t first, std::uint32_t count, double, auto) {
                     for (std::uint32_t i = first; i < first + count; ++i) {
                         ++visited[bvh.primitive_order()[i]];
                     }
                     return false;  // keep going: visit every leaf the ray reaches
                 });
    EXPECT_EQ(std::count(visited.begin(), visited.end(), 1), static_cast<std::ptrdiff_t>(boxes.size()));
}

}  // namespace
}  // namespace glint
