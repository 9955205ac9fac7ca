#include "glint/accel/wide_bvh.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_group.h>

#include <array>
#include <deque>
#include <mutex>
#include <numeric>

namespace glint {
namespace {

constexpr int kBins = 16;
// Beyond this binary depth, splits are median splits by count, which halve the range: the depth (and
// so the traversal stack) stays bounded whatever the input.
constexpr int kMedianSplitDepth = 48;
// Ranges smaller than this are built by the current task; larger ones spawn tasks.
constexpr std::size_t kParallelGrain = 4096;

double half_area(const Bounds3& b) {
    if (b.empty()) {
        return 0;
    }
    const Vec3 e = b.extent();
    return e.x * e.y + e.y * e.z + e.z * e.x;
}

// A range of primitive positions [begin, end) with its boxes.
struct Range {
    std::size_t begin = 0, end = 0;
    Bounds3 bounds;           // of the primitives
    Bounds3 centroid_bounds;  // of their centroids
    int depth = 0;            // binary splits above it
    bool is_leaf = false;     // decided: not worth splitting (or cannot be)
    std::size_t size() const { return end - begin; }
};

struct Bin {
    Bounds3 bounds;
    std::size_t count = 0;
};
using Bins = std::array<std::array<Bin, kBins>, 3>;

// float boxes that contain the double ones: rounded outwards, then padded by a relative 2^-20 so that
// the float slab arithmetic of traversal never culls a box the ray touches.
float round_down(double v) {
    float f = saturate_to_float(v);
    if (static_cast<double>(f) > v) {
        f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    }
    return f;
}
float round_up(double v) {
    float f = saturate_to_float(v);
    if (static_cast<double>(f) < v) {
        f = std::nextafter(f, std::numeric_limits<float>::infinity());
    }
    return f;
}

class Builder {
  public:
    Builder(std::span<const Bounds3> boxes, const BvhBuildOptions& options, std::vector<std::uint32_t>& order)
        : boxes_(boxes), options_(options), order_(order) {}

    std::vector<WideBvhNode> build() {
        Range root{0, boxes_.size(), {}, {}, 0, false};
        measure(root);
        nodes_.emplace_back();
        build_node(0, root);
        std::vector<WideBvhNode> nodes;
        nodes.reserve(nodes_.size());
        for (const auto& n : nodes_) {
            nodes.push_back(n);
        }
        return nodes;
    }
    Bounds3 root_bounds() const {
        Range root{0, boxes_.size(), {}, {}, 0, false};
        measure(root);
        return root.bounds;
    }

  private:
    void measure(Range& range) const {
        auto reduce = [&](std::size_t b, std::size_t e, std::pair<Bounds3, Bounds3> acc) {
            for (std::size_t i = b; i < e; ++i) {
                acc.first.grow(boxes_[order_[i]]);
                acc.second.grow(boxes_[order_[i]].center());
            }
            return acc;
        };
        std::pair<Bounds3, Bounds3> result;
        if (range.size() > kParallelGrain * 4) {
            result = tbb::parallel_reduce(
                tbb::blocked_range<std::size_t>(range.begin, range.end, kParallelGrain),
                std::pair<Bounds3, Bounds3>{},
                [&](const tbb::blocked_range<std::size_t>& r, std::pair<Bounds3, Bounds3> acc) {
                    return reduce(r.begin(), r.end(), acc);
                },
                [](std::pair<Bounds3, Bounds3> a, const std::pair<Bounds3, Bounds3>& b) {
                    a.first.grow(b.first);
                    a.second.grow(b.second);
                    return a;
                });
        } else {
            result = reduce(range.begin, range.end, {});
        }
        range.bounds = result.first;
        range.centroid_bounds = result.second;
    }

    // Which bin a centroid falls in, per axis, over the centroid bounds (the same function for binning
    // and for partitioning, so that both agree). Centroids are box centres, recomputed rather than
    // stored: a pass over the boxes is cheaper than allocating another array of them.
    struct Binning {
        Vec3 lo;
        double scale[3] = {0, 0, 0};  // bins per unit length; 0 on an axis with no extent
        explicit Binning(const Bounds3& cb) : lo(cb.lo) {
            for (int axis = 0; axis < 3; ++axis) {
                const double extent = cb.hi[axis] - cb.lo[axis];
                const double bins_per_unit = kBins / extent;
                scale[axis] = extent > 0 && std::isfinite(bins_per_unit) ? bins_per_unit : 0;
            }
        }
        int bin(const Vec3& centroid, int axis) const {
            const int b = static_cast<int>((centroid[axis] - lo[axis]) * scale[axis]);
            return std::clamp(b, 0, kBins - 1);
        }
    };

    Bins fill_bins(const Range& range) const {
        const Binning binning(range.centroid_bounds);
        auto fill = [&](std::size_t b, std::size_t e, Bins bins) {
            for (std::size_t i = b; i < e; ++i) {
                const std::uint32_t p = order_[i];
                const Vec3 centroid = boxes_[p].center();
                for (int axis = 0; axis < 3; ++axis) {
                    if (binning.scale[axis] > 0) {
                        Bin& bin = bins[axis][binning.bin(centroid, axis)];
                        bin.bounds.grow(boxes_[p]);
                        ++bin.count;
                    }
                }
            }
            return bins;
        };
        if (range.size() > kParallelGrain * 4) {
            return tbb::parallel_reduce(
                tbb::blocked_range<std::size_t>(range.begin, range.end, kParallelGrain), Bins{},
                [&](const tbb::blocked_range<std::size_t>& r, Bins acc) {
                    return fill(r.begin(), r.end(), acc);
                },
                [](Bins a, const Bins& b) {
                    for (int axis = 0; axis < 3; ++axis) {
                        for (int i = 0; i < kBins; ++i) {
                            a[axis][i].bounds.grow(b[axis][i].bounds);
                            a[axis][i].count += b[axis][i].count;
                        }
                    }
                    return a;
                });
        }
        return fill(range.begin, range.end, Bins{});
    }

    // What testing `count` primitives costs, in primitive tests.
    double tests(std::size_t count) const {
        const auto group = static_cast<std::size_t>(std::max(options_.primitives_per_test, 1));
        return static_cast<double>((count + group - 1) / group);
    }

    // Splits `range` into two, or marks it a leaf. Returns false if it became a leaf.
    bool split(Range& range, Range& left, Range& right) const {
        const std::size_t n = range.size();
        const bool can_split =
            !range.centroid_bounds.empty() && max_component(range.centroid_bounds.extent()) > 0;
        if (n <= 1 || !can_split) {
            range.is_leaf = true;  // identical centroids: no plane separates them
            return false;
        }
        std::size_t mid = 0;
        if (range.depth >= kMedianSplitDepth) {
            const Vec3 e = range.centroid_bounds.extent();
            const int axis = e.x > e.y ? (e.x > e.z ? 0 : 2) : (e.y > e.z ? 1 : 2);
            mid = range.begin + n / 2;
            std::nth_element(order_.begin() + static_cast<std::ptrdiff_t>(range.begin),
                             order_.begin() + static_cast<std::ptrdiff_t>(mid),
                             order_.begin() + static_cast<std::ptrdiff_t>(range.end),
                             [&](std::uint32_t a, std::uint32_t b) {
                                 return boxes_[a].center()[axis] < boxes_[b].center()[axis];
                             });
        } else {
            const Bins bins = fill_bins(range);
            double best_cost = kInf;
            int best_axis = -1;
            int best_bin = 0;
            for (int axis = 0; axis < 3; ++axis) {
                if (!(range.centroid_bounds.hi[axis] > range.centroid_bounds.lo[axis])) {
                    continue;
                }
                // Sweep from the right to get the cost of every plane between bins.
                std::array<double, kBins> right_cost{};
                Bounds3 acc;
                std::size_t count = 0;
                for (int i = kBins - 1; i > 0; --i) {
                    acc.grow(bins[axis][i].bounds);
                    count += bins[axis][i].count;
                    right_cost[i] = half_area(acc) * tests(count);
                }
                acc = Bounds3{};
                count = 0;
                for (int i = 0; i < kBins - 1; ++i) {
                    acc.grow(bins[axis][i].bounds);
                    count += bins[axis][i].count;
                    const double cost = half_area(acc) * tests(count) + right_cost[i + 1];
                    if (count > 0 && count < n && cost < best_cost) {
                        best_cost = cost;
                        best_axis = axis;
                        best_bin = i;
                    }
                }
            }
            const double area = half_area(range.bounds);
            const double split_cost = options_.traversal_cost + (area > 0 ? best_cost / area : tests(n));
            const double leaf_cost = tests(n);
            const bool fits_leaf = n <= static_cast<std::size_t>(options_.max_leaf_size);
            if (best_axis < 0 || (fits_leaf && leaf_cost <= split_cost)) {
                range.is_leaf = true;
                return false;
            }
            const Binning binning(range.centroid_bounds);
            const auto middle = std::partition(
                order_.begin() + static_cast<std::ptrdiff_t>(range.begin),
                order_.begin() + static_cast<std::ptrdiff_t>(range.end),
                [&](std::uint32_t p) { return binning.bin(boxes_[p].center(), best_axis) <= best_bin; });
            mid = static_cast<std::size_t>(middle - order_.begin());
            if (mid == range.begin || mid == range.end) {
                range.is_leaf = true;  // cannot happen with consistent binning; a leaf is still correct
                return false;
            }
        }
        left = Range{range.begin, mid, {}, {}, range.depth + 1, false};
        right = Range{mid, range.end, {}, {}, range.depth + 1, false};
        measure(left);
        measure(right);
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
                    half_area(children[c].bounds) > pick_area) {
                    pick = static_cast<int>(c);
                    pick_area = half_area(children[c].bounds);
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
            const Bounds3& b = child.bounds;
            const double pad = std::ldexp(std::max(max_component(abs(b.lo)), max_component(abs(b.hi))), -20);
            node.lo_x[c] = round_down(b.lo.x - pad);
            node.lo_y[c] = round_down(b.lo.y - pad);
            node.lo_z[c] = round_down(b.lo.z - pad);
            node.hi_x[c] = round_up(b.hi.x + pad);
            node.hi_y[c] = round_up(b.hi.y + pad);
            node.hi_z[c] = round_up(b.hi.z + pad);
            const bool leaf =
                child.is_leaf || child.size() <= static_cast<std::size_t>(options_.max_leaf_size);
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
            if (child.size() >= kParallelGrain) {
                group.run([this, ci = child_index, ch = child] { build_node(ci, ch); });
            } else {
                build_node(child_index, child);
            }
        }
        group.wait();
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

    std::span<const Bounds3> boxes_;
    BvhBuildOptions options_;
    std::vector<std::uint32_t>& order_;
    std::mutex mutex_;
    // A deque keeps nodes in place while other tasks append; copied to a vector at the end.
    std::deque<WideBvhNode> nodes_;
};

}  // namespace

void WideBvh::build(std::span<const Bounds3> boxes, const BvhBuildOptions& options) {
    order_.resize(boxes.size());
    std::iota(order_.begin(), order_.end(), 0u);
    nodes_.clear();
    bounds_ = Bounds3{};
    if (boxes.empty()) {
        return;
    }
    Builder builder(boxes, options, order_);
    bounds_ = builder.root_bounds();
    nodes_ = builder.build();
    nodes_.shrink_to_fit();
}

bool WideBvh::cpu_has_avx2() {
#ifdef GLINT_BVH_HAVE_AVX2_PATH
    static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    return avx2;
#else
    return false;
#endif
}

}  // namespace glint
