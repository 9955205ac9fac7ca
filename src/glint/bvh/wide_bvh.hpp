// An 8-wide bounding volume hierarchy over primitives known only by their boxes: the engine under the
// scene's BVH (whose primitives are shapes) and under each mesh (whose primitives are triangles).
//
// Build: binned SAH (16 bins per axis), parallel over subtrees with TBB. Each wide node is made by
// splitting its primitives with the SAH until it has 8 children (always opening the child of largest
// area), so no binary tree is built and then collapsed.
//
// Nodes store their children's boxes in float, structure-of-arrays, rounded outwards (so a float box
// always contains the double one). Traversal tests the 8 boxes at once with AVX2 when the CPU has it,
// with a scalar loop otherwise; both are compiled into the same binary and chosen at run time.
//
// The owner keeps its primitives in primitive_order() so that a leaf is a contiguous range [first,
// first + count), and tests them in a leaf callback: the hot loop is the caller's flat code, not a
// virtual call per primitive.
#pragma once

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

#include "glint/core/bounds.hpp"
#include "glint/core/ray.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define GLINT_BVH_HAVE_AVX2_PATH 1
#endif

namespace glint {

// double → float without undefined behaviour: values beyond float's range become ±infinity (NaN stays).
inline float saturate_to_float(double x) {
    constexpr double kMax = std::numeric_limits<float>::max();
    if (x > kMax) {
        return std::numeric_limits<float>::infinity();
    }
    if (x < -kMax) {
        return -std::numeric_limits<float>::infinity();
    }
    return static_cast<float>(x);
}

// The nearest float at or below / at or above x (a float box rounded this way contains the double one;
// a float bound rounded up never cuts off a double t).
inline float round_down_to_float(double x) {
    float f = saturate_to_float(x);
    if (static_cast<double>(f) > x) {
        f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    }
    return f;
}
inline float round_up_to_float(double x) {
    float f = saturate_to_float(x);
    if (static_cast<double>(f) < x) {
        f = std::nextafter(f, std::numeric_limits<float>::infinity());
    }
    return f;
}

struct alignas(32) WideBvhNode {
    static constexpr int kWidth = 8;
    // Child boxes; an empty slot has lo = +inf and hi = −inf, which no ray hits.
    float lo_x[kWidth], lo_y[kWidth], lo_z[kWidth];
    float hi_x[kWidth], hi_y[kWidth], hi_z[kWidth];
    std::uint32_t child[kWidth];  // inner child: node index; leaf: first primitive (in primitive order)
    std::uint32_t count[kWidth];  // 0: inner child (or empty slot); n > 0: a leaf of n primitives
};

struct BvhBuildOptions {
    int max_leaf_size = 4;      // leaves hold at most this many primitives, unless they cannot be split
    double traversal_cost = 1;  // the SAH's cost of visiting a node, relative to one primitive test
    // Primitives tested together at the same cost (the mesh tests blocks of 4 triangles at once): the
    // SAH counts a leaf of n primitives as ⌈n / group⌉ tests, which favours full groups.
    int primitives_per_test = 1;
};

class WideBvh {
  public:
    // The deepest a build goes, in binary splits (so also in wide levels): what bounds the traversal
    // stack. A range this deep is a leaf, whatever its size; no input reaches it in practice (see
    // kMedianSplitDepth in wide_bvh.cpp).
    static constexpr int kMaxDepth = 96;

    WideBvh() = default;
    // Builds over one box per primitive (at most 2^32 − 1 of them; std::length_error beyond). Any boxes
    // give a tree, in bounded time and depth: boxes beyond float's range saturate to infinity, NaN
    // bounds count as infinite, identical boxes share a leaf. (Unbounded shapes are best kept elsewhere,
    // as the scene's BVH does: a box that does not cull is tested by every ray that reaches it.)
    void build(std::span<const Bounds3> boxes, const BvhBuildOptions& options = {});
    // The same, asking `box_of(i)` for primitive i's box (from several threads at once), so that a mesh
    // need not hold an array of boxes only to hand it over.
    void build(std::size_t count, const std::function<Bounds3(std::size_t)>& box_of,
               const BvhBuildOptions& options = {});

    // The primitive stored at position i, for leaf ranges: leaves refer to positions in this order.
    const std::vector<std::uint32_t>& primitive_order() const { return order_; }
    const std::vector<WideBvhNode>& nodes() const { return nodes_; }
    const Bounds3& bounds() const { return bounds_; }
    std::size_t memory_bytes() const {
        return nodes_.capacity() * sizeof(WideBvhNode) + order_.capacity() * sizeof(std::uint32_t);
    }
    // Whether traversal uses the AVX2 path: when the CPU has AVX2 and FMA, unless a test asked for the
    // scalar path (so both paths are tested on any machine).
    static bool uses_avx2() { return avx2_in_use_.load(std::memory_order_relaxed); }
    static void force_scalar_traversal(bool on) { avx2_in_use_.store(!on && cpu_has_avx2()); }
    static bool cpu_has_avx2();

    // Nearest hit. `leaf(first, count, t_max, avx2)` tests primitives [first, first + count) for hits
    // with t in (0, t_max), lowers t_max to the nearest one found and returns whether it found any.
    // `avx2` is std::true_type when called from the AVX2 traversal (the leaf may then use AVX2 too).
    template <class Leaf>
    bool intersect(const Ray& ray, double& t_max, Leaf&& leaf) const;
    // Any hit: `leaf(first, count, t_max, avx2)` returns whether any primitive is hit before t_max.
    template <class Leaf>
    bool occluded(const Ray& ray, double t_max, Leaf&& leaf) const;
    // Nearest hits of n rays that go much the same way (a pixel's camera rays), as a packet: one walk of
    // the tree for all of them, which tests a node's boxes for each ray that entered the node, and a
    // leaf for each ray that entered the leaf, each with its own t_max. A ray alone branches on each
    // node's answer, and a branch it mispredicts or waits for stalls it; in a packet, coherent rays
    // share the branches and their box tests overlap. A ray meets every box it would meet alone, but in
    // the packet's order (the nearest of its rays' entry points first) and so sometimes a box that its
    // own hits would have culled first: the same nearest hits, except that ties in t may fall the
    // other way (the owner must settle those: BvhAccelerator traces such rays again alone).
    // `leaf(rays, first, count)` tests primitives [first, first + count) for each ray k whose bit is
    // set in `rays`, lowering t_max[k] to the nearest hit it finds, and returns the bits of the rays
    // whose t_max it lowered. At most kMaxPacket rays; without AVX2, or with a ray beyond float's
    // range (beyond_float_traversal), they go one at a time through intersect.
    static constexpr int kMaxPacket = 16;
    template <class Leaf>
    void intersect_packet(const Ray* const* rays, int n, double* t_max, Leaf&& leaf) const;

    // A ray prepared for the box tests (public for the node tests in bvh_detail).
    struct TraversalRay;

    // Lets the owner re-lay its leaves out: `f(first, count)` returns the new `first` of each leaf
    // (the mesh packs its leaves into blocks of four triangles).
    template <class F>
    void remap_leaves(F&& f) {
        for (WideBvhNode& node : nodes_) {
            for (int c = 0; c < WideBvhNode::kWidth; ++c) {
                if (node.count[c] > 0) {
                    node.child[c] = f(node.child[c], node.count[c]);
                }
            }
        }
    }

    // Where the owner keeps the data of its leaves, so that traversal can prefetch a leaf when it
    // pushes it: leaf (first, count) starts at data + first · stride bytes (after remap_leaves). The
    // data must stay where it is for the life of the tree.
    void set_leaf_data(const void* data, std::size_t stride) {
        leaf_data_ = static_cast<const char*>(data);
        leaf_stride_ = stride;
    }

  private:
    static void prefetch(const void* start, std::size_t bytes) {
        const char* p = static_cast<const char*>(start);
        for (std::size_t offset = 0; offset < std::min<std::size_t>(bytes, 512); offset += 64) {
            __builtin_prefetch(p + offset);
        }
    }
    // Starts loading a child that traversal has put aside (a node, or a leaf's data when the owner gave
    // it): it will be read soon, and traversal otherwise spends much of its time waiting for memory.
    void prefetch_child(std::uint32_t child, std::uint32_t count) const {
        if (count == 0) {
            prefetch(&nodes_[child], sizeof(WideBvhNode));
        } else if (leaf_data_ != nullptr) {
            prefetch(leaf_data_ + std::size_t{child} * leaf_stride_, leaf_stride_);
        }
    }
    // uses_avx2()'s answer, asked twice for every ray: the CPU's, found once when the program starts
    // (before main; nothing traverses a tree during static initialisation), unless a test forced the
    // scalar path.
    static inline std::atomic<bool> avx2_in_use_{cpu_has_avx2()};
    template <bool kAnyHit, class NodeTest, class Leaf>
    bool traverse(const Ray& ray, double& t_max, Leaf& leaf) const;
#ifdef GLINT_BVH_HAVE_AVX2_PATH
    template <class Leaf>
    void traverse_packet_avx2(const Ray* const* rays, int n, double* t_max, Leaf& leaf) const;
    // Every leaf in turn, for rays the box tests cannot take (beyond_float_traversal).
    template <bool kAnyHit, class Leaf>
    bool every_leaf(double& t_max, Leaf& leaf) const {
        bool found = false;
        for (const WideBvhNode& node : nodes_) {
            for (int c = 0; c < WideBvhNode::kWidth; ++c) {
                if (node.count[c] > 0 && leaf(node.child[c], node.count[c], t_max, std::false_type{})) {
                    if constexpr (kAnyHit) {
                        return true;
                    }
                    found = true;
                }
            }
        }
        return found;
    }
    // The same loop compiled for AVX2, so that the node test and the owner's leaf test are inlined.
    template <bool kAnyHit, class Leaf>
    bool traverse_avx2(const Ray& ray, double& t_max, Leaf& leaf) const;
#endif

    std::vector<WideBvhNode> nodes_;  // nodes_[0] is the root (when there are primitives)
    std::vector<std::uint32_t> order_;
    Bounds3 bounds_;
    // The largest inverse direction component traversal uses (the stand-in for 1/0 of an axis-aligned
    // ray): 1e30, or less for a tree whose coordinates times 1e30 would overflow float. The slab test
    // computes plane · inverse − origin · inverse; an overflow there gives inf − inf, or with FMA the
    // wrong infinity, and culled boxes the ray is inside (a mesh at x = 1e10 was missed by vertical
    // rays). Set by build(): kept below float's largest value over 4 · the tree's largest coordinate.
    double largest_inverse_ = 1e30;
    const char* leaf_data_ = nullptr;
    std::size_t leaf_stride_ = 0;
};

// ---- traversal (in the header so that the owner's leaf test is inlined) ------------------------------

struct WideBvh::TraversalRay {
    // Slab planes are chosen by the sign of the direction, so that an inverted (empty) box never
    // passes; t = plane · inv − origin · inv.
    float inv[3];
    float origin_inv[3];
    // The same, grown by kFarGrowth, for the far planes: plane · inv_far − origin_inv_far is where the
    // ray leaves a slab, pushed out by kFarGrowth, in one fused multiply–subtract rather than a multiply
    // after it (one step fewer on the chain of dependent operations from a node's load to its test).
    // A slab's near and far crossings are then rounded apart, not from the same terms: for a flat box
    // (a quad's) the near one may come out past the far one, and what keeps such a box is its padding
    // (set_child_box in wide_bvh.cpp, 2^-20 of its largest coordinate), several times that rounding
    // (test Bvh.FlatRectanglesFarAwayKeepEveryHit fails without the padding).
    float inv_far[3];
    float origin_inv_far[3];
    int near_offset[3];  // offset of the near plane's array (lo or hi) within a node, per axis
    int far_offset[3];

    // The far planes' relative margin, for the float rounding of the slab arithmetic (a box whose far
    // plane the ray reaches at t is kept up to t · kFarGrowth).
    static constexpr double kFarGrowth = 1 + 4e-7;

    // `largest_inverse` is the tree's (WideBvh::largest_inverse_): see there.
    TraversalRay() = default;
    TraversalRay(const Ray& ray, double largest_inverse) {
        for (int a = 0; a < 3; ++a) {
            // A zero component gives ±inf; a finite stand-in keeps 0 · inf (NaN) out of the slab test.
            double inverse = 1.0 / ray.direction[a];
            if (!(std::abs(inverse) < largest_inverse)) {
                inverse = std::signbit(ray.direction[a]) ? -largest_inverse : largest_inverse;
            }
            // |inverse| ≤ largest_inverse ≤ 1e30 fits a float: no saturation needed (saturate_to_float's
            // two tests, for three axes of every ray, were 1.4 % of the instructions of RTIOW's final scene).
            inv[a] = static_cast<float>(inverse);
            origin_inv[a] = saturate_to_float(ray.origin[a] * inverse);
            inv_far[a] = static_cast<float>(inverse * kFarGrowth);
            origin_inv_far[a] = saturate_to_float(ray.origin[a] * inverse * kFarGrowth);
            const bool negative = inv[a] < 0;
            const int lo = static_cast<int>(a * WideBvhNode::kWidth * sizeof(float));
            const int hi = lo + static_cast<int>(3 * WideBvhNode::kWidth * sizeof(float));
            near_offset[a] = negative ? hi : lo;
            far_offset[a] = negative ? lo : hi;
        }
    }
};

namespace bvh_detail {

// The float bound for a double t_max, rounded up and with a margin for the float slab arithmetic.
inline float far_limit(double t_max) {
    return saturate_to_float(t_max * (1 + 1e-6));
}

inline const float* plane(const WideBvhNode& node, int offset) {
    return reinterpret_cast<const float*>(reinterpret_cast<const unsigned char*>(&node) + offset);
}

// Which of the node's 8 boxes the ray enters before t_far (bit i for child i), and where.
struct ScalarNodeTest {
    static constexpr bool kAvx2 = false;
    static unsigned hits(const WideBvhNode& node, const WideBvh::TraversalRay& r, float t_far,
                         float* t_near_out);
};

#ifdef GLINT_BVH_HAVE_AVX2_PATH
__attribute__((target("avx2,fma"))) inline __m256 crossings(const WideBvhNode& node, int offset, float inv,
                                                            float origin_inv);

struct Avx2NodeTest {
    static constexpr bool kAvx2 = true;
    __attribute__((target("avx2,fma"))) static inline unsigned hits(const WideBvhNode& node,
                                                                    const WideBvh::TraversalRay& r,
                                                                    float t_far, float* t_near_out);
    // The same in lanes: where the ray enters each box (`t_near`), and the boxes it enters before t_far
    // (all bits set in their lanes).
    __attribute__((target("avx2,fma"))) static inline __m256 enters(const WideBvhNode& node,
                                                                    const WideBvh::TraversalRay& r,
                                                                    float t_far, __m256& t_near);
};
#endif

#ifdef GLINT_BVH_HAVE_AVX2_PATH
// The rays of a packet (bit k for t_far[k], 16 of them) whose far limit is before t_near.
__attribute__((target("avx2,fma"))) inline unsigned rays_done_before(const float* t_far, float t_near) {
    const __m256 t = _mm256_set1_ps(t_near);
    const auto low =
        static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(_mm256_load_ps(t_far), t, _CMP_LT_OQ)));
    const auto high =
        static_cast<unsigned>(_mm256_movemask_ps(_mm256_cmp_ps(_mm256_load_ps(t_far + 8), t, _CMP_LT_OQ)));
    return low | high << 8;
}
#endif

// A pending subtree: what the stack holds.
struct StackEntry {
    std::uint32_t child;
    std::uint32_t count;
    float t_near;
};

}  // namespace bvh_detail

inline unsigned bvh_detail::ScalarNodeTest::hits(const WideBvhNode& node, const WideBvh::TraversalRay& r,
                                                 float t_far, float* t_near_out) {
    const float* near_x = plane(node, r.near_offset[0]);
    const float* near_y = plane(node, r.near_offset[1]);
    const float* near_z = plane(node, r.near_offset[2]);
    const float* far_x = plane(node, r.far_offset[0]);
    const float* far_y = plane(node, r.far_offset[1]);
    const float* far_z = plane(node, r.far_offset[2]);
    unsigned mask = 0;
    for (int i = 0; i < WideBvhNode::kWidth; ++i) {
        // max(acc, x) keeps acc when x is NaN: a slab that cannot be evaluated does not cull.
        float t0 = 0;
        t0 = std::max(t0, near_x[i] * r.inv[0] - r.origin_inv[0]);
        t0 = std::max(t0, near_y[i] * r.inv[1] - r.origin_inv[1]);
        t0 = std::max(t0, near_z[i] * r.inv[2] - r.origin_inv[2]);
        float t1 = t_far;
        t1 = std::min(t1, far_x[i] * r.inv_far[0] - r.origin_inv_far[0]);
        t1 = std::min(t1, far_y[i] * r.inv_far[1] - r.origin_inv_far[1]);
        t1 = std::min(t1, far_z[i] * r.inv_far[2] - r.origin_inv_far[2]);
        t_near_out[i] = t0;
        mask |= (t0 <= t1 ? 1u : 0u) << i;
    }
    return mask;
}

#ifdef GLINT_BVH_HAVE_AVX2_PATH
// plane · inv − origin · inv for one plane of each of the node's 8 boxes: where the ray crosses it.
// (A function, not a lambda: GCC would not compile a lambda's body for AVX2.)
__attribute__((target("avx2,fma"))) inline __m256 bvh_detail::crossings(const WideBvhNode& node, int offset,
                                                                        float inv, float origin_inv) {
    return _mm256_fmsub_ps(_mm256_load_ps(plane(node, offset)), _mm256_set1_ps(inv),
                           _mm256_set1_ps(origin_inv));
}

__attribute__((target("avx2,fma"))) inline unsigned bvh_detail::Avx2NodeTest::hits(
    const WideBvhNode& node, const WideBvh::TraversalRay& r, float t_far, float* t_near_out) {
    __m256 t_near;
    const __m256 entered = enters(node, r, t_far, t_near);
    _mm256_storeu_ps(t_near_out, t_near);
    return static_cast<unsigned>(_mm256_movemask_ps(entered));
}

__attribute__((target("avx2,fma"))) inline __m256 bvh_detail::Avx2NodeTest::enters(
    const WideBvhNode& node, const WideBvh::TraversalRay& r, float t_far, __m256& t_near) {
    const __m256 near_x = crossings(node, r.near_offset[0], r.inv[0], r.origin_inv[0]);
    const __m256 near_y = crossings(node, r.near_offset[1], r.inv[1], r.origin_inv[1]);
    const __m256 near_z = crossings(node, r.near_offset[2], r.inv[2], r.origin_inv[2]);
    const __m256 far_x = crossings(node, r.far_offset[0], r.inv_far[0], r.origin_inv_far[0]);
    const __m256 far_y = crossings(node, r.far_offset[1], r.inv_far[1], r.origin_inv_far[1]);
    const __m256 far_z = crossings(node, r.far_offset[2], r.inv_far[2], r.origin_inv_far[2]);
    // Two levels of max and of min, not a chain of three: the test is on the chain of dependent
    // operations from a node's load to the next node's (RTIOW's final scene: 0.991 of the time).
    // _mm256_max_ps(a, b) returns b when either is NaN, so a slab that cannot be evaluated never culls,
    // as in the scalar test: a NaN y term leaves the z term; a NaN z term makes the inner max (or min)
    // NaN, and the outer one then keeps the x term with 0 (or t_far), dropping y too (a box kept
    // that the scalar test might cull: more tests, the same hits).
    const __m256 t0 =
        _mm256_max_ps(_mm256_max_ps(near_y, near_z), _mm256_max_ps(near_x, _mm256_setzero_ps()));
    const __m256 t1 = _mm256_min_ps(_mm256_min_ps(far_y, far_z), _mm256_min_ps(far_x, _mm256_set1_ps(t_far)));
    t_near = t0;
    return _mm256_cmp_ps(t0, t1, _CMP_LE_OQ);
}
#endif

template <bool kAnyHit, class NodeTest, class Leaf>
__attribute__((always_inline)) inline bool WideBvh::traverse(const Ray& ray, double& t_max,
                                                             Leaf& leaf) const {
    using bvh_detail::StackEntry;
    if (nodes_.empty()) {
        return false;
    }
    const TraversalRay r(ray, largest_inverse_);
    // The build bounds the depth (kMaxDepth), and each level adds at most 7 entries (8 pushed, 1 popped).
    constexpr int kStackSize = 1024;
    static_assert(kStackSize >= (WideBvhNode::kWidth - 1) * kMaxDepth + 1);
    StackEntry stack[kStackSize];
    int top = 0;
    bool found = false;
    float t_far = bvh_detail::far_limit(t_max);
    alignas(32) float t_near[WideBvhNode::kWidth];
    StackEntry entry{0, 0, 0.0f};  // the root
    while (true) {
        if (entry.count > 0) {
            if (leaf(entry.child, entry.count, t_max, std::bool_constant<NodeTest::kAvx2>{})) {
                if constexpr (kAnyHit) {
                    return true;
                }
                found = true;
                t_far = bvh_detail::far_limit(t_max);
            }
        } else {
            const WideBvhNode& node = nodes_[entry.child];
            unsigned mask = NodeTest::hits(node, r, t_far, t_near);
            const unsigned others = mask & (mask - 1);  // the hit children but the first
            if (mask != 0 && others == 0) {
                // One child hit (the common case deep in the tree): go on with it, no stack round trip.
                const int i = __builtin_ctz(mask);
                entry = {node.child[i], node.count[i], t_near[i]};
                continue;
            }
            if (others != 0 && (others & (others - 1)) == 0) {
                // Two children hit (the next most common case): go on with the one the loop below would
                // pop first and push only the other (RTIOW's final scene: 2.0 % fewer instructions, 0.973 of
                // the time).
                const int i = __builtin_ctz(mask);
                const int k = __builtin_ctz(others);
                // The loop pushes i, then k above it unless i is strictly nearer.
                const bool k_first = kAnyHit || !(t_near[i] < t_near[k]);
                const int later = k_first ? i : k;
                const int now = k_first ? k : i;
                prefetch_child(node.child[later], node.count[later]);
                stack[top++] = {node.child[later], node.count[later], t_near[later]};
                entry = {node.child[now], node.count[now], t_near[now]};
                continue;
            }
            // Nearest hit: push the children far to near, so the nearest is visited first (its hit
            // then culls the others). Any hit: push them as they come. Any occluder will do, and the
            // nearest box of a shadow ray is usually the surface it leaves, rarely what blocks it:
            // visiting it first made the dragon's shadow rays 25 % slower (bench/accel.cpp).
            const int base = top;
            while (mask != 0) {
                const int i = __builtin_ctz(mask);
                mask &= mask - 1;
                const StackEntry e{node.child[i], node.count[i], t_near[i]};
                // Read soon: at once, if it is the next one popped (the nearest for a nearest hit, the
                // last pushed for any hit).
                prefetch_child(e.child, e.count);
                int j = top++;
                while (!kAnyHit && j > base && stack[j - 1].t_near < e.t_near) {
                    stack[j] = stack[j - 1];
                    --j;
                }
                stack[j] = e;
            }
        }
        // The next pending subtree that may still hold a hit nearer than the nearest found.
        do {
            if (top == 0) {
                return found;
            }
            entry = stack[--top];
        } while (entry.t_near > t_far);
    }
}

#ifdef GLINT_BVH_HAVE_AVX2_PATH
template <bool kAnyHit, class Leaf>
__attribute__((target("avx2,fma"))) bool WideBvh::traverse_avx2(const Ray& ray, double& t_max,
                                                                Leaf& leaf) const {
    return traverse<kAnyHit, bvh_detail::Avx2NodeTest>(ray, t_max, leaf);
}
#endif

// A ray that starts (or points) beyond what float traversal can represent, such as a shadow ray from a
// point on a sphere of radius 1e116, would turn the slab tests into inf − inf; it is answered by testing
// every leaf in turn. Such rays occur only in scenes beyond float's range.
inline bool beyond_float_traversal(const Ray& ray) {
    constexpr double kLargest = 1e30;
    return !(std::abs(ray.origin.x) < kLargest && std::abs(ray.origin.y) < kLargest &&
             std::abs(ray.origin.z) < kLargest && std::isfinite(ray.direction.x) &&
             std::isfinite(ray.direction.y) && std::isfinite(ray.direction.z));
}

template <class Leaf>
bool WideBvh::intersect(const Ray& ray, double& t_max, Leaf&& leaf) const {
    if (beyond_float_traversal(ray)) [[unlikely]] {
        return every_leaf<false>(t_max, leaf);
    }
#ifdef GLINT_BVH_HAVE_AVX2_PATH
    if (uses_avx2()) {
        return traverse_avx2<false>(ray, t_max, leaf);
    }
#endif
    return traverse<false, bvh_detail::ScalarNodeTest>(ray, t_max, leaf);
}

template <class Leaf>
bool WideBvh::occluded(const Ray& ray, double t_max, Leaf&& leaf) const {
    if (beyond_float_traversal(ray)) [[unlikely]] {
        return every_leaf<true>(t_max, leaf);
    }
#ifdef GLINT_BVH_HAVE_AVX2_PATH
    if (uses_avx2()) {
        return traverse_avx2<true>(ray, t_max, leaf);
    }
#endif
    return traverse<true, bvh_detail::ScalarNodeTest>(ray, t_max, leaf);
}

#ifdef GLINT_BVH_HAVE_AVX2_PATH
template <class Leaf>
__attribute__((target("avx2,fma"))) void WideBvh::traverse_packet_avx2(const Ray* const* rays, int n,
                                                                       double* t_max, Leaf& leaf) const {
    // A pending subtree and the rays that entered its box.
    struct PacketEntry {
        std::uint32_t child;
        std::uint32_t count;
        std::uint32_t rays;  // bit k: ray k entered the box before its t_far of the time
        float t_near;        // the nearest of their entry points
    };
    TraversalRay r[kMaxPacket];
    // Every ray's far limit, 16 lanes for the tests on popping (rays beyond n never enter anything).
    static_assert(kMaxPacket == 16);
    alignas(32) float t_far[kMaxPacket];
    for (int k = 0; k < kMaxPacket; ++k) {
        t_far[k] = -std::numeric_limits<float>::infinity();
    }
    for (int k = 0; k < n; ++k) {
        r[k] = TraversalRay(*rays[k], largest_inverse_);
        t_far[k] = bvh_detail::far_limit(t_max[k]);
    }
    constexpr int kStackSize = 1024;
    static_assert(kStackSize >= (WideBvhNode::kWidth - 1) * kMaxDepth + 1);
    PacketEntry stack[kStackSize];
    int top = 0;
    PacketEntry entry{0, 0, (1u << n) - 1, 0.0f};  // the root, entered by all
    const __m256 infinity = _mm256_set1_ps(std::numeric_limits<float>::infinity());
    while (true) {
        if (entry.count > 0) {
            for (unsigned lowered = leaf(entry.rays, entry.child, entry.count); lowered != 0;
                 lowered &= lowered - 1) {
                const int k = __builtin_ctz(lowered);
                t_far[k] = bvh_detail::far_limit(t_max[k]);
            }
        } else {
            // Each ray in the box tests the node's 8 boxes, as Avx2NodeTest does; their answers are
            // gathered per child: which rays enter it (bit k of a lane) and the nearest entry point.
            const WideBvhNode& node = nodes_[entry.child];
            __m256i rays_in = _mm256_setzero_si256();
            __m256 nearest = infinity;
            for (unsigned m = entry.rays; m != 0; m &= m - 1) {
                const int k = __builtin_ctz(m);
                __m256 t0;
                const __m256 entered = bvh_detail::Avx2NodeTest::enters(node, r[k], t_far[k], t0);
                nearest = _mm256_min_ps(nearest, _mm256_blendv_ps(infinity, t0, entered));
                rays_in = _mm256_or_si256(
                    rays_in, _mm256_and_si256(_mm256_castps_si256(entered), _mm256_set1_epi32(1 << k)));
            }
            alignas(32) std::uint32_t rays_of[WideBvhNode::kWidth];
            alignas(32) float t_near[WideBvhNode::kWidth];
            _mm256_store_si256(reinterpret_cast<__m256i*>(rays_of), rays_in);
            _mm256_store_ps(t_near, nearest);
            unsigned mask = static_cast<unsigned>(
                _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpgt_epi32(rays_in, _mm256_setzero_si256()))));
            if (mask != 0 && (mask & (mask - 1)) == 0) {
                const int i = __builtin_ctz(mask);
                entry = {node.child[i], node.count[i], rays_of[i], t_near[i]};
                continue;
            }
            // Far to near, as the single ray's traversal pushes them, by the nearest entry point.
            const int base = top;
            while (mask != 0) {
                const int i = __builtin_ctz(mask);
                mask &= mask - 1;
                const PacketEntry e{node.child[i], node.count[i], rays_of[i], t_near[i]};
                prefetch_child(e.child, e.count);
                int j = top++;
                while (j > base && stack[j - 1].t_near < e.t_near) {
                    stack[j] = stack[j - 1];
                    --j;
                }
                stack[j] = e;
            }
        }
        // The next pending subtree, with the rays that may still find a nearer hit in it: a ray enters
        // the box no sooner than the entry's t_near, so one whose t_far is below that is done with it.
        while (true) {
            if (top == 0) {
                return;
            }
            entry = stack[--top];
            entry.rays &= ~bvh_detail::rays_done_before(t_far, entry.t_near);
            if (entry.rays != 0) {
                break;
            }
        }
    }
}
#endif

template <class Leaf>
void WideBvh::intersect_packet(const Ray* const* rays, int n, double* t_max, Leaf&& leaf) const {
    assert(n <= kMaxPacket);
    if (n <= 0 || nodes_.empty()) {
        return;
    }
#ifdef GLINT_BVH_HAVE_AVX2_PATH
    bool fits = uses_avx2();
    for (int k = 0; k < n && fits; ++k) {
        fits = !beyond_float_traversal(*rays[k]);
    }
    if (fits) {
        traverse_packet_avx2(rays, n, t_max, leaf);
        return;
    }
#endif
    for (int k = 0; k < n; ++k) {
        intersect(*rays[k], t_max[k], [&](std::uint32_t first, std::uint32_t count, double&, auto) {
            return leaf(1u << k, first, count) != 0;
        });
    }
}

}  // namespace glint
