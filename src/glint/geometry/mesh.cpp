// Mesh {type: mesh, file: bunny.obj}: a triangle mesh read from an OBJ or PLY file.
#include "glint/geometry/mesh.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "glint/geometry/triangle.hpp"
#include "glint/params/build_context.hpp"
#include "glint/params/params.hpp"

namespace glint {
namespace {

// f(i) for every i in [0, n), in parallel.
template <class F>
void for_each_index(std::size_t n, F&& f) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i < r.end(); ++i) {
                              f(i);
                          }
                      });
}

bool usable_normal(const Vec3& n) {
    const double l2 = length_squared(n);
    return std::isfinite(l2) && l2 > 1e-30;
}

// The checks that keep a mesh made by code (not by a loader, which checks more and says where) from
// reading out of bounds: counts, indices, and positions the triangle test can compute with.
void check_mesh_data(const MeshData& data) {
    const MeshLimits limits;
    if (data.triangles.size() > limits.max_triangles) {
        throw std::invalid_argument("the mesh has " + std::to_string(data.triangles.size()) +
                                    " triangles, more than the limit of " +
                                    mesh_io::limit_text(limits.max_triangles));
    }
    if (!data.normals.empty() && data.normals.size() != data.positions.size()) {
        throw std::invalid_argument("the mesh has " + std::to_string(data.normals.size()) + " normals for " +
                                    std::to_string(data.positions.size()) +
                                    " positions (expected one per position, or none)");
    }
    for (std::size_t v = 0; v < data.positions.size(); ++v) {
        if (!is_finite(data.positions[v])) {
            throw std::invalid_argument("vertex " + std::to_string(v) + " of the mesh is not finite");
        }
    }
    for (std::size_t t = 0; t < data.triangles.size(); ++t) {
        for (std::uint32_t v : data.triangles[t]) {
            if (v >= data.positions.size()) {
                throw std::invalid_argument(
                    "triangle " + std::to_string(t) + " of the mesh refers to vertex " + std::to_string(v) +
                    ", but there are " + std::to_string(data.positions.size()) + " vertices");
            }
        }
    }
}

}  // namespace

Mesh::Mesh(MeshData data) {
    check_mesh_data(data);
    positions_ = std::move(data.positions);
    normals_ = std::move(data.normals);
    const auto start = std::chrono::steady_clock::now();
    triangles_.reserve(data.triangles.size());
    for (const auto& tri : data.triangles) {
        const Vec3 n =
            cross(positions_[tri[1]] - positions_[tri[0]], positions_[tri[2]] - positions_[tri[0]]);
        if (length_squared(n) > 0) {
            triangles_.push_back(tri);
        }
    }
    if (triangles_.empty()) {
        throw std::invalid_argument("the mesh has no triangle with a non-zero area");
    }
    if (!normals_.empty()) {
        // Broken normals (zero, NaN, infinite) become the area-weighted mean of the faces around them.
        if (!std::all_of(normals_.begin(), normals_.end(), usable_normal)) {
            std::vector<Vec3> from_faces(positions_.size());
            for (const auto& tri : triangles_) {
                const Vec3 n =
                    cross(positions_[tri[1]] - positions_[tri[0]], positions_[tri[2]] - positions_[tri[0]]);
                for (std::uint32_t v : tri) {
                    from_faces[v] += n;
                }
            }
            for (std::size_t v = 0; v < normals_.size(); ++v) {
                if (!usable_normal(normals_[v])) {
                    normals_[v] = from_faces[v];
                }
            }
        }
        for (Vec3& n : normals_) {
            n = usable_normal(n) ? normalize(n) : Vec3{};  // zero: shade with the face's normal
        }
    }
    // The passes over all triangles run in parallel (a 1.6 M-triangle mesh spends a third of its build
    // outside the BVH otherwise); each writes only its own elements, so the result is the same.
    BvhBuildOptions options;
    options.max_leaf_size = 2 * TriangleBlock::kLanes;
    options.primitives_per_test = TriangleBlock::kLanes;
    bvh_.build(
        triangles_.size(),
        [this](std::size_t i) {
            Bounds3 box;
            for (std::uint32_t v : triangles_[i]) {
                box.grow(positions_[v]);
            }
            return box;
        },
        options);
    // Store the triangles in BVH order, so that a leaf is a contiguous run of the array.
    std::vector<std::array<std::uint32_t, 3>> ordered(triangles_.size());
    for_each_index(ordered.size(),
                   [&](std::size_t i) { ordered[i] = triangles_[bvh_.primitive_order()[i]]; });
    triangles_ = std::move(ordered);
    // Each leaf's triangles go into blocks of four: the block starts are a running count over the
    // leaves, then the blocks are filled in parallel. They are allocated once, at their exact count.
    struct Leaf {
        std::uint32_t first, count, block;
    };
    std::vector<Leaf> leaves;
    std::uint32_t block_count = 0;
    bvh_.remap_leaves([&](std::uint32_t first, std::uint32_t count) {
        leaves.push_back({first, count, block_count});
        block_count += (count + TriangleBlock::kLanes - 1) / TriangleBlock::kLanes;
        return leaves.back().block;
    });
    blocks_.resize(block_count);
    for_each_index(leaves.size(), [&](std::size_t l) {
        const Leaf& leaf = leaves[l];
        const std::uint32_t lanes =
            (leaf.count + TriangleBlock::kLanes - 1) / TriangleBlock::kLanes * TriangleBlock::kLanes;
        for (std::uint32_t i = 0; i < lanes; ++i) {
            TriangleBlock& block = blocks_[leaf.block + i / TriangleBlock::kLanes];
            const int lane = static_cast<int>(i % TriangleBlock::kLanes);
            if (i < leaf.count) {
                const auto& tri = triangles_[leaf.first + i];
                block.set(lane, leaf.first + i, positions_[tri[0]], positions_[tri[1]], positions_[tri[2]]);
            } else {
                block.set_empty(lane);
            }
        }
    });
    bvh_.set_leaf_data(blocks_.data(), sizeof(TriangleBlock));
    // Areas in parallel, then their running sum in order (so the sum does not depend on the threads).
    area_cdf_.resize(triangles_.size());
    for_each_index(triangles_.size(), [&](std::size_t i) {
        const auto& tri = triangles_[i];
        area_cdf_[i] = 0.5 * length(cross(positions_[tri[1]] - positions_[tri[0]],
                                          positions_[tri[2]] - positions_[tri[0]]));
    });
    double sum = 0;
    for (double& a : area_cdf_) {
        sum += a;
        a = sum;
    }
    build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::size_t Mesh::memory_bytes() const {
    return positions_.capacity() * sizeof(Vec3) + normals_.capacity() * sizeof(Vec3) +
           triangles_.capacity() * sizeof(triangles_[0]) + blocks_.capacity() * sizeof(TriangleBlock) +
           area_cdf_.capacity() * sizeof(double) + bvh_.memory_bytes();
}

void Mesh::fill_hit(std::uint32_t index, const Vec3& p0, const Vec3& p1, const Vec3& p2,
                    const TriangleHit& at, Hit& hit) const {
    const double b0 = at.b0, b1 = at.b1, b2 = at.b2;
    hit.t = at.t;
    // The barycentric point lies on the triangle up to rounding, whatever t was.
    hit.point = b0 * p0 + b1 * p1 + b2 * p2;
    hit.normal = normalize(cross(p1 - p0, p2 - p0));
    hit.shading_normal = hit.normal;
    if (!normals_.empty()) {
        const auto& tri = triangles_[index];
        const Vec3 n = b0 * normals_[tri[0]] + b1 * normals_[tri[1]] + b2 * normals_[tri[2]];
        if (usable_normal(n)) {
            const Vec3 unit = normalize(n);
            hit.shading_normal = dot(unit, hit.normal) < 0 ? -unit : unit;
        }
    }
    hit.uv = {b1, b2};
    hit.error = kHitRelativeError *
                std::max({max_component(abs(p0)), max_component(abs(p1)), max_component(abs(p2))});
    hit.element = index;
}

namespace {

// The leaf test of the mesh's BVH: the triangle blocks [first, first + ⌈count / 4⌉), nearest hit or
// any hit. The AVX2 overload is compiled for AVX2 like the traversal that calls it, so that the block
// test is inlined into the traversal loop (a call would spill every vector register there); the other
// runs on any CPU. Their bodies differ only in the block test, and are written out twice on purpose:
// shared code (a lambda, a template) would be compiled without the AVX2 target and block the inlining.
template <bool kAnyHit>
struct BlockLeaf {
    const WatertightRay& ray;
    const TriangleBlock* blocks;
    TriangleHit best{};                         // the nearest hit so far (nearest-hit only)
    const TriangleBlock* best_block = nullptr;  // its block
    int best_lane = 0;                          // and lane

    static std::uint32_t block_end(std::uint32_t first, std::uint32_t count) {
        return first + (count + TriangleBlock::kLanes - 1) / TriangleBlock::kLanes;
    }
    // What a hit in `lane` of block b means: the end of an any-hit query, or a nearer t.
    bool take(std::uint32_t b, int lane, double& t_limit) {
        if constexpr (!kAnyHit) {
            t_limit = best.t;
            best_block = &blocks[b];
            best_lane = lane;
        }
        return true;
    }

    bool operator()(std::uint32_t first, std::uint32_t count, double& t_limit, std::false_type) {
        bool any = false;
        for (std::uint32_t b = first; b < block_end(first, count); ++b) {
            const int lane = intersect_block_scalar(ray, blocks[b], t_limit, best);
            if (lane >= 0) {
                any = take(b, lane, t_limit);
                if constexpr (kAnyHit) {
                    return true;
                }
            }
        }
        return any;
    }
#if defined(__x86_64__) || defined(__i386__)
    __attribute__((target("avx2,fma"))) bool operator()(std::uint32_t first, std::uint32_t count,
                                                        double& t_limit, std::true_type) {
        bool any = false;
        for (std::uint32_t b = first; b < block_end(first, count); ++b) {
            const int lane = intersect_block_avx2(ray, blocks[b], t_limit, best);
            if (lane >= 0) {
                any = take(b, lane, t_limit);
                if constexpr (kAnyHit) {
                    return true;
                }
            }
        }
        return any;
    }
#endif
};

}  // namespace

bool Mesh::intersect(const Ray& ray, double t_max, Hit& hit) const {
    const WatertightRay wray(ray);
    BlockLeaf<false> leaf{wray, blocks_.data()};
    if (!bvh_.intersect(ray, t_max, leaf)) {
        return false;
    }
    const TriangleBlock& block = *leaf.best_block;
    const int lane = leaf.best_lane;
    fill_hit(block.element[lane], block.vertex(0, lane), block.vertex(1, lane), block.vertex(2, lane),
             leaf.best, hit);
    return true;
}

bool Mesh::occluded(const Ray& ray, double t_max) const {
    const WatertightRay wray(ray);
    return bvh_.occluded(ray, t_max, BlockLeaf<true>{wray, blocks_.data()});
}

bool Mesh::intersect_triangle(std::uint32_t index, const Ray& ray, double t_max, Hit& hit) const {
    const auto& tri = triangles_[index];
    const Vec3& p0 = positions_[tri[0]];
    const Vec3& p1 = positions_[tri[1]];
    const Vec3& p2 = positions_[tri[2]];
    TriangleHit h;
    if (!glint::intersect_triangle(WatertightRay(ray), p0, p1, p2, t_max, h)) {
        return false;
    }
    fill_hit(index, p0, p1, p2, h, hit);
    return true;
}

bool Mesh::hits_triangle(std::uint32_t index, const Ray& ray, double t_max) const {
    const auto& tri = triangles_[index];
    TriangleHit unused;
    return glint::intersect_triangle(WatertightRay(ray), positions_[tri[0]], positions_[tri[1]],
                                     positions_[tri[2]], t_max, unused);
}

std::optional<ShapeSample> Mesh::sample_area(Point2 u) const {
    // A triangle with probability proportional to its area, then a uniform point in it.
    const double target = u.x * area();
    const auto it = std::upper_bound(area_cdf_.begin(), area_cdf_.end(), target);
    const std::size_t index =
        std::min<std::size_t>(static_cast<std::size_t>(it - area_cdf_.begin()), area_cdf_.size() - 1);
    const double before = index == 0 ? 0 : area_cdf_[index - 1];
    const double width = area_cdf_[index] - before;
    const double ux =
        width > 0 ? std::clamp((target - before) / width, 0.0, 1.0) : 0.5;  // reuse u.x's remainder
    const double su = std::sqrt(ux);
    const double b1 = 1 - su;
    const double b2 = u.y * su;
    const auto& tri = triangles_[index];
    const Vec3& p0 = positions_[tri[0]];
    const Vec3& p1 = positions_[tri[1]];
    const Vec3& p2 = positions_[tri[2]];
    const Vec3 point = (1 - b1 - b2) * p0 + b1 * p1 + b2 * p2;
    return ShapeSample{point, normalize(cross(p1 - p0, p2 - p0)), 1 / area()};
}

std::unique_ptr<Shape> Mesh::create(Params& params, const BuildContext& context) {
    const std::string file = params.string("file");
    MeshData data = load_mesh_file(context.resolve(file), params.pos_of("file"));
    try {
        return std::make_unique<Mesh>(std::move(data));
    } catch (const std::invalid_argument& e) {
        params.fail("file", "mesh '" + file + "': " + e.what());
    }
}

}  // namespace glint
