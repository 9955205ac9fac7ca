#include "glint/bvh/wide_bvh.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_group.h>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <array>
#include <bit>
#include <deque>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>

#include "glint/core/cpu.hpp"

namespace glint {
namespace {

constexpr int kBins = 16;
// Beyond this binary depth, splits are median splits by count, which halve the range: the depth (and
// so the traversal stack) stays bounded whatever the input. 32 halvings bring any range of up to 2^32
// primitives down to one, so no range ever reaches WideBvh::kMaxDepth, which a range becomes a leaf at
// all the same (a second guarantee that the recursion ends, whatever the boxes).
constexpr int kMedianSplitDepth = 48;
static_assert(kMedianSplitDepth + 32 < WideBvh::kMaxDepth);
// Ranges of at least this many primitives are built by their own task.
constexpr std::size_t kTaskGrain = 4096;
// Ranges of at least this many primitives are binned and partitioned by several threads, in chunks of
// kChunk. The chunks depend only on the range, never on the thread count, so the tree does not either.
constexpr std::size_t kParallelSplit = 1 << 18;
constexpr std::size_t kChunk = 1 << 13;

// Four floats operated on together: SSE on x86-64 (always present there), a plain loop elsewhere. The
// build's boxes are kept in these, lanes x, y, z and one unused, so that growing a box is two
// instructions instead of six compare-and-branch pairs.
#if defined(__SSE2__)
using F4 = __m128;
inline F4 load4(const float* p) {
    return _mm_load_ps(p);
}
inline F4 splat4(float v) {
    return _mm_set1_ps(v);
}
inline F4 add4(F4 a, F4 b) {
    return _mm_add_ps(a, b);
}
inline F4 sub4(F4 a, F4 b) {
    return _mm_sub_ps(a, b);
}
inline F4 mul4(F4 a, F4 b) {
    return _mm_mul_ps(a, b);
}
// The second operand is returned when either is NaN: min4(x, acc) keeps acc for a NaN x.
inline F4 min4(F4 x, F4 acc) {
    return _mm_min_ps(x, acc);
}
inline F4 max4(F4 x, F4 acc) {
    return _mm_max_ps(x, acc);
}
inline void store4(float* p, F4 v) {
    _mm_store_ps(p, v);
}
#else
struct F4 {
    float v[4];
};
inline F4 load4(const float* p) {
    return {{p[0], p[1], p[2], p[3]}};
}
inline F4 splat4(float v) {
    return {{v, v, v, v}};
}
template <class Op>
inline F4 map4(F4 a, F4 b, Op op) {
    return {{op(a.v[0], b.v[0]), op(a.v[1], b.v[1]), op(a.v[2], b.v[2]), op(a.v[3], b.v[3])}};
}
inline F4 add4(F4 a, F4 b) {
    return map4(a, b, [](float x, float y) { return x + y; });
}
inline F4 sub4(F4 a, F4 b) {
    return map4(a, b, [](float x, float y) { return x - y; });
}
inline F4 mul4(F4 a, F4 b) {
    return map4(a, b, [](float x, float y) { return x * y; });
}
inline F4 min4(F4 x, F4 acc) {
    return map4(x, acc, [](float a, float b) { return a < b ? a : b; });
}
inline F4 max4(F4 x, F4 acc) {
    return map4(x, acc, [](float a, float b) { return a > b ? a : b; });
}
inline void store4(float* p, F4 v) {
    std::copy(v.v, v.v + 4, p);
}
#endif

// A primitive as the build sees it: its box in float (rounded outwards) and its index, 32 bytes. The
// build moves these rather than indices into the caller's boxes, so that every pass reads memory in
// order instead of jumping through an index array into 48-byte double boxes. The index rides in the
// unused fourth lane of `lo`, as bits (copies of a float keep its bits, and the lane is never computed
// with).
struct alignas(16) PrimRef {
    float lo[4];
    float hi[4];
    std::uint32_t id() const { return std::bit_cast<std::uint32_t>(lo[3]); }
    F4 lo4() const { return load4(lo); }
    F4 hi4() const { return load4(hi); }
    // Twice the box centre: the factor 2 is the same everywhere, so it never needs undoing.
    F4 centroid2() const { return add4(lo4(), hi4()); }
    float centroid2(int axis) const { return lo[axis] + hi[axis]; }
};

// A float box, empty by default (lo > hi). Lane 3 is not part of it.
struct Box {
    F4 lo = splat4(std::numeric_limits<float>::infinity());
    F4 hi = splat4(-std::numeric_limits<float>::infinity());

    void grow(const Box& b) {
        lo = min4(b.lo, lo);
        hi = max4(b.hi, hi);
    }
    void grow(const PrimRef& p) {
        lo = min4(p.lo4(), lo);
        hi = max4(p.hi4(), hi);
    }
    void grow_point(F4 p) {
        lo = min4(p, lo);
        hi = max4(p, hi);
    }
    struct Corners {
        alignas(16) float lo[4];
        alignas(16) float hi[4];
    };
    Corners corners() const {
        Corners c;
        store4(c.lo, lo);
        store4(c.hi, hi);
        return c;
    }
    // Half the surface area, in double: the SAH compares sums of these. 0 for an empty box. Always
    // finite: an extent beyond float's range (a box saturated to infinity) counts as the largest float
    // extent, so that the SAH still compares costs (inf · 0 would be NaN, and inf costs all tie).
    double half_area() const {
        const Corners c = corners();
        if (!(c.lo[0] <= c.hi[0] && c.lo[1] <= c.hi[1] && c.lo[2] <= c.hi[2])) {
            return 0;
        }
        const double x = clamp_extent(double{c.hi[0]} - c.lo[0]), y = clamp_extent(double{c.hi[1]} - c.lo[1]),
                     z = clamp_extent(double{c.hi[2]} - c.lo[2]);
        return x * y + y * z + z * x;
    }
    static double clamp_extent(double extent) {
        constexpr double kLargest = 2.0 * std::numeric_limits<float>::max();
        return extent <= kLargest ? extent : kLargest;  // inf and NaN (inf − inf) alike
    }
};

// A range of primitive positions [begin, end) with its boxes.
struct Range {
    std::size_t begin = 0, end = 0;
    Box bounds;            // of the primitives
    Box centroid_bounds;   // of their (doubled) centroids
    int depth = 0;         // binary splits above it
    bool is_leaf = false;  // decided: not worth splitting (or cannot be)
    std::size_t size() const { return end - begin; }
};

// The sides of a split and their boxes, as one pass of partitioning measures them.
struct Sides {
    Box left, left_centroids, right, right_centroids;
    std::size_t left_count = 0;
    void add(const PrimRef& p, bool left_side) {
        if (left_side) {
            left.grow(p);
            left_centroids.grow_point(p.centroid2());
            ++left_count;
        } else {
            right.grow(p);
            right_centroids.grow_point(p.centroid2());
        }
    }
    void merge(const Sides& o) {
        left.grow(o.left);
        left_centroids.grow(o.left_centroids);
        right.grow(o.right);
        right_centroids.grow(o.right_centroids);
        left_count += o.left_count;
    }
};

struct Bin {
    Box bounds;
    std::size_t count = 0;
};
using Bins = std::array<std::array<Bin, kBins>, 3>;

// Which bin a centroid falls in, per axis, over the centroid bounds (the same function for binning and
// for partitioning, so that both agree).
struct Binning {
    alignas(16) float lo[4] = {0, 0, 0, 0};
    alignas(16) float scale[4] = {0, 0, 0, 0};  // bins per unit length; 0 on an axis that cannot be split
    explicit Binning(const Box& centroid_bounds) {
        const Box::Corners cb = centroid_bounds.corners();
        for (int axis = 0; axis < 3; ++axis) {
            lo[axis] = cb.lo[axis];
            const float extent = cb.hi[axis] - cb.lo[axis];
            // Slightly fewer than kBins per extent, so that the largest centroid still lands in the last bin.
            const float bins_per_unit = kBins * (1 - 1e-6f) / extent;
            scale[axis] = extent > 0 && std::isfinite(bins_per_unit) && bins_per_unit > 0 ? bins_per_unit : 0;
        }
    }
    bool can_split() const { return scale[0] > 0 || scale[1] > 0 || scale[2] > 0; }
    // The bins of `p` on the three axes (lane 3 is meaningless). max4(·, 0) turns NaN into 0 and the min
    // keeps the value in range, so the conversion to int is always defined.
    void bins(const PrimRef& p, int* out) const {
        F4 f = mul4(sub4(p.centroid2(), load4(lo)), load4(scale));
        f = min4(max4(f, splat4(0)), splat4(kBins - 1));
        alignas(16) float v[4];
        store4(v, f);
        for (int axis = 0; axis < 3; ++axis) {
            out[axis] = static_cast<int>(v[axis]);
        }
    }
    int bin(const PrimRef& p, int axis) const {
        const float f = (p.centroid2(axis) - lo[axis]) * scale[axis];
        const float at_least_zero = f > 0 ? f : 0;  // NaN → 0
        return static_cast<int>(at_least_zero < kBins - 1 ? at_least_zero : kBins - 1);
    }
};

class Builder {
  public:
    // Reads the boxes in parallel, measuring the root range on the way; returns the boxes' exact
    // (double) union through `bounds`.
    Builder(std::size_t count, const std::function<Bounds3(std::size_t)>& box_of,
            const BvhBuildOptions& options, Bounds3& bounds)
        : options_(options), count_(count), refs_(new PrimRef[count]) {
        struct Measure {
            Bounds3 exact;
            Box boxes, centroids;
        };
        const Measure all = tbb::parallel_reduce(
            tbb::blocked_range<std::size_t>(0, count_, kChunk), Measure{},
            [&](const tbb::blocked_range<std::size_t>& r, Measure acc) {
                for (std::size_t i = r.begin(); i < r.end(); ++i) {
                    const Bounds3 b = box_of(i);
                    acc.exact.grow(b);
                    refs_[i] = PrimRef{{lower_bound(b.lo.x), lower_bound(b.lo.y), lower_bound(b.lo.z),
                                        std::bit_cast<float>(static_cast<std::uint32_t>(i))},
                                       {upper_bound(b.hi.x), upper_bound(b.hi.y), upper_bound(b.hi.z), 0}};
                    acc.boxes.grow(refs_[i]);
                    acc.centroids.grow_point(refs_[i].centroid2());
                }
                return acc;
            },
            [](Measure a, const Measure& b) {
                // min and max are exact: the order of the pieces does not matter.
                a.exact.grow(b.exact);
                a.boxes.grow(b.boxes);
                a.centroids.grow(b.centroids);
                return a;
            });
        bounds = all.exact;
        root_ = Range{0, count_, all.boxes, all.centroids, 0, false};
    }

    // Builds the tree; returns its nodes, and the primitive order through `order`.
    std::vector<WideBvhNode> build(std::vector<std::uint32_t>& order) {
        nodes_.emplace_back();
        build_node(0, root_);
        // Tasks allocate nodes in whatever order they run; renumbering them depth-first makes the layout
        // the same for any thread count, and puts each subtree's nodes together in memory.
        std::vector<WideBvhNode> nodes;
        nodes.reserve(nodes_.size());
        std::vector<std::pair<std::uint32_t, std::size_t>> pending{{0u, 0}};  // (built index, parent slot)
        while (!pending.empty()) {
            const auto [built, parent_slot] = pending.back();
            pending.pop_back();
            const auto index = static_cast<std::uint32_t>(nodes.size());
            if (!nodes.empty()) {
                nodes[parent_slot / WideBvhNode::kWidth].child[parent_slot % WideBvhNode::kWidth] = index;
            }
            nodes.push_back(nodes_[built]);
            for (int c = WideBvhNode::kWidth - 1; c >= 0; --c) {
                // An empty slot is child 0, count 0: the root is nobody's child.
                if (nodes.back().count[c] == 0 && nodes.back().child[c] != 0) {
                    pending.emplace_back(nodes.back().child[c], std::size_t{index} * WideBvhNode::kWidth + c);
                }
            }
        }
        order.resize(count_);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count_, kChunk), [&](const auto& r) {
            for (std::size_t i = r.begin(); i < r.end(); ++i) {
                order[i] = refs_[i].id();
            }
        });
        return nodes;
    }

  private:
    // A box's bounds in float, rounded outwards; a NaN bound (a box that cannot be evaluated) becomes
    // infinite, so that the box still contains whatever the primitive is.
    static float lower_bound(double lo) {
        return std::isnan(lo) ? -std::numeric_limits<float>::infinity() : round_down_to_float(lo);
    }
    static float upper_bound(double hi) {
        return std::isnan(hi) ? std::numeric_limits<float>::infinity() : round_up_to_float(hi);
    }

    // The chunks of a large range; each is processed whole by one thread, and results are combined in
    // chunk order.
    static std::size_t chunk_count(const Range& range) { return (range.size() + kChunk - 1) / kChunk; }
    static std::size_t chunk_begin(const Range& range, std::size_t c) { return range.begin + c * kChunk; }
    static std::size_t chunk_end(const Range& range, std::size_t c) {
        return std::min(range.end, chunk_begin(range, c + 1));
    }

    static void add_to_bins(const PrimRef& p, const Binning& binning, Bins& bins) {
        int bin[3];
        binning.bins(p, bin);
        for (int axis = 0; axis < 3; ++axis) {
            bins[axis][bin[axis]].bounds.grow(p);
            ++bins[axis][bin[axis]].count;
        }
    }

    static void merge_bins(Bins& into, const Bins& from) {
        for (int axis = 0; axis < 3; ++axis) {
            for (int i = 0; i < kBins; ++i) {
                into[axis][i].bounds.grow(from[axis][i].bounds);
                into[axis][i].count += from[axis][i].count;
            }
        }
    }

    void fill_bins(std::size_t begin, std::size_t end, const Binning& binning, Bins& bins) const {
        // Neighbouring primitives mostly fall in the same bins, so each update would wait for the one
        // before it to be stored: alternate between two sets of bins to halve that chain.
        constexpr std::size_t kTwoBanks = 64;
        if (end - begin < kTwoBanks) {
            for (std::size_t i = begin; i < end; ++i) {
                add_to_bins(refs_[i], binning, bins);
            }
            return;
        }
        Bins odd;
        std::size_t i = begin;
        for (; i + 1 < end; i += 2) {
            add_to_bins(refs_[i], binning, bins);
            add_to_bins(refs_[i + 1], binning, odd);
        }
        if (i < end) {
            add_to_bins(refs_[i], binning, bins);
        }
        merge_bins(bins, odd);
    }

    void fill_bins(const Range& range, const Binning& binning, Bins& bins) const {
        if (range.size() < kParallelSplit) {
            fill_bins(range.begin, range.end, binning, bins);
            return;
        }
        bins = tbb::parallel_reduce(
            tbb::blocked_range<std::size_t>(range.begin, range.end, kChunk), Bins{},
            [&](const tbb::blocked_range<std::size_t>& r, Bins acc) {
                fill_bins(r.begin(), r.end(), binning, acc);
                return acc;
            },
            [](Bins a, const Bins& b) {
                merge_bins(a, b);
                return a;
            });
    }

    // Moves the primitives `goes_left` picks to the front of the range, measuring both sides as it goes.
    // Returns the sides; the left one is [begin, begin + left_count).
    template <class GoesLeft>
    Sides partition(const Range& range, GoesLeft goes_left) {
        if (range.size() < kParallelSplit) {
            return partition_serial(range.begin, range.end, goes_left);
        }
        // Large ranges: each chunk counts and measures its sides, then every chunk copies its
        // primitives to their place in the scratch array (a stable partition), which is copied back.
        const std::size_t chunks = chunk_count(range);
        std::vector<Sides> sides(chunks);
        tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
            for (std::size_t i = chunk_begin(range, c); i < chunk_end(range, c); ++i) {
                sides[c].add(refs_[i], goes_left(refs_[i]));
            }
        });
        std::vector<std::size_t> left_at(chunks), right_at(chunks);
        Sides total;
        for (std::size_t c = 0; c < chunks; ++c) {
            total.merge(sides[c]);
        }
        std::size_t left = range.begin, right = range.begin + total.left_count;
        for (std::size_t c = 0; c < chunks; ++c) {
            left_at[c] = left;
            right_at[c] = right;
            left += sides[c].left_count;
            right += chunk_end(range, c) - chunk_begin(range, c) - sides[c].left_count;
        }
        scratch();
        tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
            std::size_t l = left_at[c], r = right_at[c];
            for (std::size_t i = chunk_begin(range, c); i < chunk_end(range, c); ++i) {
                scratch_[goes_left(refs_[i]) ? l++ : r++] = refs_[i];
            }
        });
        tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t c) {
            std::copy(scratch_.get() + chunk_begin(range, c), scratch_.get() + chunk_end(range, c),
                      refs_.get() + chunk_begin(range, c));
        });
        return total;
    }

    template <class GoesLeft>
    Sides partition_serial(std::size_t begin, std::size_t end, GoesLeft goes_left) {
        Sides sides;
        std::size_t i = begin, j = end;
        while (true) {
            while (i < j && goes_left(refs_[i])) {
                sides.add(refs_[i++], true);
            }
            while (i < j && !goes_left(refs_[j - 1])) {
                sides.add(refs_[--j], false);
            }
            if (i >= j) {
                break;
            }
            std::swap(refs_[i], refs_[j - 1]);
            sides.add(refs_[i++], true);
            sides.add(refs_[--j], false);
        }
        return sides;
    }

    // The scratch array of the parallel partition, allocated on first use (disjoint ranges use disjoint
    // parts of it, so concurrent tasks share it).
    void scratch() {
        std::call_once(scratch_once_, [&] { scratch_.reset(new PrimRef[count_]); });
    }

    // What testing `count` primitives costs, in primitive tests.
    double tests(std::size_t count) const {
        const auto group = static_cast<std::size_t>(std::max(options_.primitives_per_test, 1));
        return static_cast<double>((count + group - 1) / group);
    }

    // The axis for a median split: the longest the binning can split; else one along which the
    // centroids still differ, by more than float can bin (some are infinite); -1 if they are all equal.
    static int median_axis(const Range& range, const Binning& binning) {
        int axis = -1;
        for (int a = 0; a < 3; ++a) {
            if (binning.scale[a] > 0 && (axis < 0 || binning.scale[a] < binning.scale[axis])) {
                axis = a;  // the longest axis has the fewest bins per unit
            }
        }
        if (axis < 0) {
            const Box::Corners c = range.centroid_bounds.corners();
            for (int a = 0; a < 3; ++a) {
                if (c.lo[a] < c.hi[a]) {
                    return a;
                }
            }
        }
        return axis;
    }

    // Splits the range in two halves by count along `axis`: always progress (both halves are non-empty
    // for n >= 2), whatever the boxes. NaN centroids (from infinite boxes: −inf + inf) sort first, so
    // that the comparison is a strict weak order.
    Sides median_split(const Range& range, int axis) {
        const auto key = [axis](const PrimRef& p) {
            const float c = p.centroid2(axis);
            return std::isnan(c) ? -std::numeric_limits<float>::infinity() : c;
        };
        const std::size_t mid = range.begin + range.size() / 2;
        std::nth_element(refs_.get() + range.begin, refs_.get() + mid, refs_.get() + range.end,
                         [&](const PrimRef& a, const PrimRef& b) {
                             const float ka = key(a), kb = key(b);
                             return ka < kb || (ka == kb && a.id() < b.id());
                         });
        Sides sides;
        for (std::size_t i = range.begin; i < range.end; ++i) {
            sides.add(refs_[i], i < mid);
        }
        return sides;
    }

    // Splits `range` into two, or marks it a leaf. Returns false if it became a leaf. Every split leaves
    // both sides non-empty, so the recursion always ends; and a range at kMaxDepth is a leaf whatever
    // its size (no input gets there: see kMedianSplitDepth).
    bool split(Range& range, Range& left, Range& right) {
        const std::size_t n = range.size();
        if (n <= 1 || range.depth >= WideBvh::kMaxDepth) {
            range.is_leaf = true;
            return false;
        }
        const Binning binning(range.centroid_bounds);
        const bool fits_leaf = n <= static_cast<std::size_t>(options_.max_leaf_size);
        const int halving_axis = median_axis(range, binning);
        if (halving_axis < 0 || (fits_leaf && !binning.can_split())) {
            range.is_leaf = true;  // identical centroids: no plane separates them
            return false;
        }
        Sides sides;
        if (range.depth >= kMedianSplitDepth || !binning.can_split()) {
            // Deep, or centroids spread further than float can bin (some infinite): halve by count.
            sides = median_split(range, halving_axis);
        } else {
            Bins bins;
            fill_bins(range, binning, bins);
            double best_cost = kInf;
            int best_axis = -1;
            int best_bin = 0;
            for (int axis = 0; axis < 3; ++axis) {
                if (binning.scale[axis] == 0) {
                    continue;
                }
                // Sweep from the right to get the cost of every plane between bins. A plane next to an
                // empty bin splits like its neighbour, so only planes after non-empty bins are costed
                // (small ranges leave most bins empty, and this loop is most of their build time).
                std::array<double, kBins> right_cost{};  // [0] is never read
                Box acc;
                std::size_t count = 0;
                double cost_so_far = 0;
                for (int i = kBins - 1; i > 0; --i) {
                    if (bins[axis][i].count > 0) {
                        acc.grow(bins[axis][i].bounds);
                        count += bins[axis][i].count;
                        cost_so_far = acc.half_area() * tests(count);
                    }
                    right_cost[i] = cost_so_far;
                }
                acc = Box{};
                count = 0;
                for (int i = 0; i < kBins - 1; ++i) {
                    if (bins[axis][i].count == 0) {
                        continue;
                    }
                    acc.grow(bins[axis][i].bounds);
                    count += bins[axis][i].count;
                    if (count == n) {
                        break;
                    }
                    const double cost = acc.half_area() * tests(count) + right_cost[i + 1];
                    if (cost < best_cost) {
                        best_cost = cost;
                        best_axis = axis;
                        best_bin = i;
                    }
                }
            }
            const double area = range.bounds.half_area();
            const double split_cost = options_.traversal_cost + (area > 0 ? best_cost / area : tests(n));
            const double leaf_cost = tests(n);
            if (fits_leaf && (best_axis < 0 || leaf_cost <= split_cost)) {
                range.is_leaf = true;
                return false;
            }
            // With finite areas (half_area is always finite) a splittable range always has a best
            // plane, and the partition matches the binning; the median split is the fallback that
            // guarantees progress should either ever fail.
            if (best_axis >= 0) {
                sides =
                    partition(range, [&](const PrimRef& p) { return binning.bin(p, best_axis) <= best_bin; });
            }
            if (best_axis < 0 || sides.left_count == 0 || sides.left_count == n) {
                sides = median_split(range, halving_axis);
            }
        }
        const std::size_t mid = range.begin + sides.left_count;
        left = Range{range.begin, mid, sides.left, sides.left_centroids, range.depth + 1, false};
        right = Range{mid, range.end, sides.right, sides.right_centroids, range.depth + 1, false};
        return true;
    }

    // Fills nodes_[index] from `range`, recursing (in parallel for large ranges) into inner children.
    void build_node(std::size_t index, Range range) {
        std::vector<Range> children{range};
        while (children.size() < WideBvhNode::kWidth) {
            // Open the largest child that may still be split.
            int pick = -1;
            double pick_area = -1;
            for (std::size_t c = 0; c < children.size(); ++c) {
                if (!children[c].is_leaf && children[c].size() > 1 &&
                    children[c].bounds.half_area() > pick_area) {
                    pick = static_cast<int>(c);
                    pick_area = children[c].bounds.half_area();
                }
            }
            if (pick < 0) {
                break;
            }
            Range left, right;
            if (split(children[static_cast<std::size_t>(pick)], left, right)) {
                children[static_cast<std::size_t>(pick)] = left;
                children.push_back(right);
            }
        }
        // A range still larger than a leaf may hold becomes an inner node (unless it cannot be split).
        WideBvhNode node;
        std::vector<std::pair<std::size_t, Range>> inner;
        for (int c = 0; c < WideBvhNode::kWidth; ++c) {
            if (c >= static_cast<int>(children.size())) {
                node.lo_x[c] = node.lo_y[c] = node.lo_z[c] = std::numeric_limits<float>::infinity();
                node.hi_x[c] = node.hi_y[c] = node.hi_z[c] = -std::numeric_limits<float>::infinity();
                node.child[c] = 0;
                node.count[c] = 0;
                continue;
            }
            const Range& child = children[static_cast<std::size_t>(c)];
            set_child_box(node, c, child.bounds);
            // A node of one child is a leaf (the loop above only stops at one child when the range
            // could not be split): never an inner node of the same range again, for ever.
            const bool leaf = child.is_leaf || children.size() == 1 ||
                              child.size() <= static_cast<std::size_t>(options_.max_leaf_size);
            if (leaf) {
                node.child[c] = static_cast<std::uint32_t>(child.begin);
                node.count[c] = static_cast<std::uint32_t>(child.size());
            } else {
                const std::size_t child_index = allocate();
                node.child[c] = static_cast<std::uint32_t>(child_index);
                node.count[c] = 0;
                inner.emplace_back(child_index, child);
            }
        }
        store(index, node);
        tbb::task_group group;
        for (const auto& [child_index, child] : inner) {
            if (child.size() >= kTaskGrain) {
                group.run([this, ci = child_index, ch = child] { build_node(ci, ch); });
            } else {
                build_node(child_index, child);
            }
        }
        group.wait();
    }

    // The child's box, padded by a relative 2^-20 so that the float slab arithmetic of traversal never
    // culls a box the ray touches (a flat box's near and far crossings are rounded apart: see
    // WideBvh::TraversalRay::inv_far).
    static void set_child_box(WideBvhNode& node, int c, const Box& box) {
        const Box::Corners b = box.corners();
        double magnitude = 0;
        for (int a = 0; a < 3; ++a) {
            magnitude = std::max({magnitude, std::abs(double{b.lo[a]}), std::abs(double{b.hi[a]})});
        }
        const double pad = std::ldexp(magnitude, -20);
        node.lo_x[c] = round_down_to_float(b.lo[0] - pad);
        node.lo_y[c] = round_down_to_float(b.lo[1] - pad);
        node.lo_z[c] = round_down_to_float(b.lo[2] - pad);
        node.hi_x[c] = round_up_to_float(b.hi[0] + pad);
        node.hi_y[c] = round_up_to_float(b.hi[1] + pad);
        node.hi_z[c] = round_up_to_float(b.hi[2] + pad);
    }

    std::size_t allocate() {
        const std::lock_guard lock(mutex_);
        nodes_.emplace_back();
        return nodes_.size() - 1;
    }
    void store(std::size_t index, const WideBvhNode& node) {
        const std::lock_guard lock(mutex_);
        nodes_[index] = node;
    }

    BvhBuildOptions options_;
    std::size_t count_;
    Range root_;  // all the primitives, measured by the constructor
    std::unique_ptr<PrimRef[]> refs_;
    std::unique_ptr<PrimRef[]> scratch_;
    std::once_flag scratch_once_;
    std::mutex mutex_;
    // A deque keeps nodes in place while other tasks append; copied to a vector at the end.
    std::deque<WideBvhNode> nodes_;
};

}  // namespace

void WideBvh::build(std::span<const Bounds3> boxes, const BvhBuildOptions& options) {
    build(
        boxes.size(), [boxes](std::size_t i) { return boxes[i]; }, options);
}

void WideBvh::build(std::size_t count, const std::function<Bounds3(std::size_t)>& box_of,
                    const BvhBuildOptions& options) {
    order_.clear();
    nodes_.clear();
    bounds_ = Bounds3{};
    largest_inverse_ = 1e30;
    if (count == 0) {
        return;
    }
    if (count > std::numeric_limits<std::uint32_t>::max()) {
        // Leaves and the primitive order hold 32-bit positions.
        throw std::length_error("a BVH holds at most 2^32 - 1 primitives, not " + std::to_string(count));
    }
    Builder builder(count, box_of, options, bounds_);
    nodes_ = builder.build(order_);
    nodes_.shrink_to_fit();
    // Below 8.5e7 (all ordinary scenes) this is 1e30. It is never less than 2^20: the child boxes are
    // padded by 2^-20 of their coordinates, so a ray inside a box still gets a far slab beyond its
    // other slabs' near ones (trees beyond 1e26 or so are beyond what float traversal can answer).
    const double magnitude = std::max(max_component(abs(bounds_.lo)), max_component(abs(bounds_.hi)));
    if (magnitude * 1e30 > std::numeric_limits<float>::max() / 4) {
        largest_inverse_ = std::max(0x1p20, std::numeric_limits<float>::max() / 4 / magnitude);
    }
}

bool WideBvh::cpu_has_avx2() {
#ifdef GLINT_BVH_HAVE_AVX2_PATH
    return cpu_has_avx2_and_fma();
#else
    return false;
#endif
}

}  // namespace glint
