// Mesh {type: mesh, file: bunny.obj}: a triangle mesh read from an OBJ or PLY file, or given inline.
#include "glint/geometry/mesh.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "glint/core/frame.hpp"
#include "glint/geometry/mesh_io/gltf_file.hpp"
#include "glint/geometry/triangle.hpp"
#include "glint/image/image_lookup.hpp"
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
    if (!data.uvs.empty() && data.uvs.size() != data.positions.size()) {
        throw std::invalid_argument("the mesh has " + std::to_string(data.uvs.size()) +
                                    " texture coordinates for " + std::to_string(data.positions.size()) +
                                    " positions (expected one per position, or none)");
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

// Per-vertex tangents from the uvs (Lengyel's method, "Computing Tangent Space Basis Vectors for an
// Arbitrary Mesh", 2001): each triangle's dp/du and dp/dv, solved from its edges and uv differences,
// summed at its vertices; then at each vertex the sum of dp/du made orthogonal to the vertex's normal
// (Gram–Schmidt), with w the sign that makes w · normal × tangent point along the summed dp/dv. On a
// surface whose uv mapping is affine per connected flat patch this is the exact tangent frame, the one
// MikkTSpace (glTF's reference) gives too; on curved meshes the two may differ slightly, where MikkTSpace
// also splits vertices at uv seams and weights by corner angles. Triangles whose uvs are degenerate add
// nothing; a vertex left without a tangent gets one from its normal alone (any perpendicular), so a
// normal map there tilts in an arbitrary but fixed direction.
std::vector<std::array<double, 4>> tangents_from_uvs(
    const std::vector<Vec3>& positions, const std::vector<Vec3>& normals, const std::vector<Point2>& uvs,
    const std::vector<std::array<std::uint32_t, 3>>& triangles) {
    std::vector<Vec3> along_u(positions.size()), along_v(positions.size()), face_normals(positions.size());
    for (const auto& tri : triangles) {
        const Vec3 e1 = positions[tri[1]] - positions[tri[0]], e2 = positions[tri[2]] - positions[tri[0]];
        const double du1 = uvs[tri[1]].x - uvs[tri[0]].x, dv1 = uvs[tri[1]].y - uvs[tri[0]].y;
        const double du2 = uvs[tri[2]].x - uvs[tri[0]].x, dv2 = uvs[tri[2]].y - uvs[tri[0]].y;
        const double det = du1 * dv2 - du2 * dv1;
        const Vec3 face = cross(e1, e2);
        for (std::uint32_t v : tri) {
            face_normals[v] += face;
        }
        if (!(std::abs(det) > 0) || !std::isfinite(1 / det)) {
            continue;
        }
        const Vec3 dpdu = (e1 * dv2 - e2 * dv1) / det, dpdv = (e2 * du1 - e1 * du2) / det;
        if (!is_finite(dpdu) || !is_finite(dpdv)) {
            continue;
        }
        for (std::uint32_t v : tri) {
            along_u[v] += dpdu;
            along_v[v] += dpdv;
        }
    }
    std::vector<std::array<double, 4>> tangents(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const Vec3 n = !normals.empty() && usable_normal(normals[v]) ? normalize(normals[v])
                       : usable_normal(face_normals[v])              ? normalize(face_normals[v])
                                                                     : Vec3{0, 0, 1};
        Vec3 t = along_u[v] - n * dot(n, along_u[v]);
        if (!usable_normal(t)) {
            t = Frame::from_normal(n).s;
        }
        t = normalize(t);
        const double w = dot(cross(n, t), along_v[v]) < 0 ? -1.0 : 1.0;
        tangents[v] = {t.x, t.y, t.z, w};
    }
    return tangents;
}

}  // namespace

Mesh::Mesh(MeshData data) {
    check_mesh_data(data);
    positions_ = std::move(data.positions);
    normals_ = std::move(data.normals);
    uvs_ = std::move(data.uvs);
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
           uvs_.capacity() * sizeof(Point2) + triangles_.capacity() * sizeof(triangles_[0]) +
           blocks_.capacity() * sizeof(TriangleBlock) + area_cdf_.capacity() * sizeof(double) +
           bvh_.memory_bytes() + tangents_.capacity() * sizeof(tangents_[0]) +
           (normal_map_ ? normal_map_->image.rgb.capacity() * sizeof(float) : 0);
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
    if (uvs_.empty()) {
        hit.uv = {b1, b2};
    } else {
        const auto& tri = triangles_[index];
        const Point2 &t0 = uvs_[tri[0]], &t1 = uvs_[tri[1]], &t2 = uvs_[tri[2]];
        hit.uv = {b0 * t0.x + b1 * t1.x + b2 * t2.x, b0 * t0.y + b1 * t1.y + b2 * t2.y};
    }
    hit.error = kHitRelativeError *
                std::max({max_component(abs(p0)), max_component(abs(p1)), max_component(abs(p2))});
    hit.element = index;
    if (normal_map_) [[unlikely]] {
        map_normal(index, at, hit);
    }
}

void Mesh::map_normal(std::uint32_t index, const TriangleHit& at, Hit& hit) const {
    const auto& tri = triangles_[index];
    const double b[3] = {at.b0, at.b1, at.b2};
    // The frame at the hit, unturned: the interpolated vertex normal (or the face's), the interpolated
    // tangent made perpendicular to it, and the bitangent w · n × t.
    Vec3 n = hit.normal;
    if (!normals_.empty()) {
        const Vec3 interpolated = b[0] * normals_[tri[0]] + b[1] * normals_[tri[1]] + b[2] * normals_[tri[2]];
        if (usable_normal(interpolated)) {
            n = normalize(interpolated);
        }
    }
    Vec3 t;
    double w = 0;
    for (int k = 0; k < 3; ++k) {
        const auto& tangent = tangents_[tri[static_cast<std::size_t>(k)]];
        t += b[k] * Vec3{tangent[0], tangent[1], tangent[2]};
        w += b[k] * tangent[3];
    }
    t -= n * dot(n, t);
    const Rgb texel = lookup_bilinear_repeat(normal_map_->image, hit.uv);
    const double x = (2 * texel.r - 1) * normal_map_->scale, y = (2 * texel.g - 1) * normal_map_->scale;
    const double z = 2 * texel.b - 1;
    Vec3 mapped = n;
    // A texel of (0.5, 0.5, 1), glTF's "no change", leaves the normal exactly as it is.
    if ((x != 0 || y != 0 || z <= 0) && usable_normal(t)) {
        t = normalize(t);
        const Vec3 bitangent = cross(n, t) * (w < 0 ? -1.0 : 1.0);
        const Vec3 m = x * t + y * bitangent + z * n;
        if (usable_normal(m)) {
            mapped = normalize(m);
        }
    }
    // Turned, like the interpolated normal, to the side of the face; a normal the map tilts below the
    // face (possible at grazing tilts) is not a direction any light leaves from: the unmapped one stays.
    const double side = dot(n, hit.normal) < 0 ? -1.0 : 1.0;
    hit.shading_normal = dot(mapped, hit.normal) * side > 0 ? mapped * side : n * side;
}

void Mesh::set_normal_map(Image image, double scale, std::vector<std::array<double, 4>> tangents) {
    if (uvs_.empty()) {
        throw std::invalid_argument("a normal map needs the mesh's texture coordinates, and it has none");
    }
    if (image.width <= 0 || image.height <= 0) {
        throw std::invalid_argument("a normal map needs at least one pixel");
    }
    if (!tangents.empty() && tangents.size() != positions_.size()) {
        throw std::invalid_argument("the mesh has " + std::to_string(tangents.size()) + " tangents for " +
                                    std::to_string(positions_.size()) +
                                    " positions (expected one per position, or none)");
    }
    const auto usable_tangent = [](const std::array<double, 4>& t) {
        return usable_normal({t[0], t[1], t[2]}) && std::isfinite(t[3]);
    };
    if (tangents.empty() || !std::all_of(tangents.begin(), tangents.end(), usable_tangent)) {
        tangents = tangents_from_uvs(positions_, normals_, uvs_, triangles_);
    }
    tangents_ = std::move(tangents);
    normal_map_ = std::make_unique<const NormalMap>(NormalMap{std::move(image), scale});
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

namespace {

// The faces of `data` that an OBJ file puts under `usemtl name` ("" for those before any usemtl).
void keep_obj_material(MeshData& data, const ObjMaterialUse& use, const std::string& name, Params& params) {
    std::uint32_t wanted = ObjMaterialUse::kNoMaterial;
    if (!name.empty()) {
        std::vector<std::string> names;
        for (std::uint32_t i = 0; i < use.materials.size(); ++i) {
            names.push_back(use.materials[i].name);
            if (use.materials[i].name == name) {
                wanted = i;
            }
        }
        if (wanted == ObjMaterialUse::kNoMaterial) {
            params.fail("obj_material", unknown_name_message("OBJ material", name, names, "the file uses"));
        }
    }
    std::vector<std::array<std::uint32_t, 3>> kept;
    for (std::size_t t = 0; t < data.triangles.size(); ++t) {
        if (use.triangle_material[t] == wanted) {
            kept.push_back(data.triangles[t]);
        }
    }
    if (kept.empty()) {
        params.fail("obj_material",
                    "the OBJ file has no faces " + (name.empty() ? std::string("before its first usemtl")
                                                                 : "under usemtl '" + name + "'"));
    }
    data.triangles = std::move(kept);
}

// A flat list of numbers under `key`, `per_item` to an item; at most `max_items` items.
std::vector<double> flat_numbers(Params& params, const std::string& key, std::size_t per_item,
                                 std::uint64_t max_items) {
    const Node* list = params.node(key);
    if (!list) {
        return {};
    }
    if (!list->is_sequence() || list->items.size() % per_item != 0) {
        params.fail(key, "expected a flat list of numbers, " + std::to_string(per_item) + " for each item");
    }
    if (list->items.size() / per_item > max_items) {
        params.fail(key, "more than " + mesh_io::limit_text(max_items) + " items");
    }
    std::vector<double> numbers;
    numbers.reserve(list->items.size());
    for (const Node& item : list->items) {
        numbers.push_back(node_number(item, params.what() + "." + key));
    }
    return numbers;
}

// {positions: [...], indices: [...], normals: [...], uvs: [...]}: a mesh written in the scene (what the
// importers make of meshes given inline, as pbrt's trianglemesh).
MeshData inline_mesh(Params& params) {
    const MeshLimits limits;
    MeshData data;
    const std::vector<double> positions = flat_numbers(params, "positions", 3, limits.max_vertices);
    const std::vector<double> indices = flat_numbers(params, "indices", 3, limits.max_triangles);
    const std::vector<double> normals = flat_numbers(params, "normals", 3, limits.max_vertices);
    const std::vector<double> uvs = flat_numbers(params, "uvs", 2, limits.max_vertices);
    const std::size_t vertices = positions.size() / 3;
    for (std::size_t i = 0; i < positions.size(); i += 3) {
        data.positions.push_back({positions[i], positions[i + 1], positions[i + 2]});
        if (max_component(abs(data.positions.back())) > kMaxMeshCoordinate) {
            params.fail("positions", "position " + std::to_string(i / 3) + " is beyond float's range");
        }
    }
    for (std::size_t i = 0; i < indices.size(); i += 3) {
        std::array<std::uint32_t, 3> triangle{};
        for (std::size_t k = 0; k < 3; ++k) {
            const double index = indices[i + k];
            if (!(index >= 0 && index < static_cast<double>(vertices)) || index != std::floor(index)) {
                params.fail("indices", "index " + std::to_string(i + k) +
                                           " is not a whole number from 0 to " + std::to_string(vertices) +
                                           " - 1 (the number of positions)");
            }
            triangle[k] = static_cast<std::uint32_t>(index);
        }
        data.triangles.push_back(triangle);
    }
    for (std::size_t i = 0; i < normals.size(); i += 3) {
        data.normals.push_back({normals[i], normals[i + 1], normals[i + 2]});
    }
    for (std::size_t i = 0; i < uvs.size(); i += 2) {
        data.uvs.push_back({uvs[i], uvs[i + 1]});
    }
    if (!normals.empty() && data.normals.size() != vertices) {
        params.fail("normals",
                    "expected one normal for each of the " + std::to_string(vertices) + " positions");
    }
    if (!uvs.empty() && data.uvs.size() != vertices) {
        params.fail("uvs", "expected one uv for each of the " + std::to_string(vertices) + " positions");
    }
    return data;
}

// The triangles of a glTF mesh: one primitive (`gltf_primitive`) or all of them together.
MeshData gltf_mesh(Params& params, const std::filesystem::path& path) {
    const std::shared_ptr<const GltfFile> file = load_gltf_file(path, params.pos_of("file"));
    const auto index = [&](const char* key) {
        const std::int64_t value = params.integer(key, 0);
        if (value < 0 || value > std::numeric_limits<int>::max()) {
            params.fail(key, std::string(key) + " must be a whole number ≥ 0");
        }
        return static_cast<int>(value);
    };
    const int mesh = index("gltf_mesh");
    if (params.has("gltf_primitive")) {
        return gltf_primitive_mesh(*file, mesh, index("gltf_primitive"), params.pos_of("gltf_primitive"));
    }
    MeshData all;
    for (int primitive = 0; primitive < gltf_primitive_count(*file, mesh, params.pos_of("gltf_mesh"));
         ++primitive) {
        MeshData part = gltf_primitive_mesh(*file, mesh, primitive, params.pos_of("gltf_mesh"));
        const auto offset = static_cast<std::uint32_t>(all.positions.size());
        // Normals and uvs are kept only when every primitive has them.
        const bool normals = (primitive == 0 || !all.normals.empty()) && !part.normals.empty();
        const bool uvs = (primitive == 0 || !all.uvs.empty()) && !part.uvs.empty();
        all.positions.insert(all.positions.end(), part.positions.begin(), part.positions.end());
        if (normals) {
            all.normals.insert(all.normals.end(), part.normals.begin(), part.normals.end());
        } else {
            all.normals.clear();
        }
        if (uvs) {
            all.uvs.insert(all.uvs.end(), part.uvs.begin(), part.uvs.end());
        } else {
            all.uvs.clear();
        }
        for (auto triangle : part.triangles) {
            all.triangles.push_back({triangle[0] + offset, triangle[1] + offset, triangle[2] + offset});
        }
    }
    return all;
}

bool is_gltf(const std::string& file) {
    const std::string extension = mesh_io::lower_case_extension(file);
    return extension == ".gltf" || extension == ".glb";
}

}  // namespace

std::unique_ptr<Shape> Mesh::create(Params& params, const BuildContext& context) {
    MeshData data;
    std::string what = "mesh";
    if (params.has("file") || !params.has("positions")) {
        const std::string file = params.string("file");
        what = "mesh '" + file + "'";
        if (is_gltf(file)) {
            data = gltf_mesh(params, context.resolve(file));
        } else if (params.has("obj_material")) {
            const std::string material = params.string("obj_material");
            ObjMaterialUse use;
            data = load_obj(context.resolve(file), {}, params.pos_of("file"), &use);
            keep_obj_material(data, use, material, params);
        } else {
            data = load_mesh_file(context.resolve(file), params.pos_of("file"));
        }
    } else {
        data = inline_mesh(params);
    }
    std::vector<std::array<double, 4>> tangents = std::move(data.tangents);
    std::unique_ptr<Mesh> mesh;
    try {
        mesh = std::make_unique<Mesh>(std::move(data));
    } catch (const std::invalid_argument& e) {
        params.fail(params.has("file") ? "file" : "positions", what + ": " + e.what());
    }
    if (const Node* map = params.node("normal_map")) {
        // {file: n.png, gltf_image: N, scale: 1}: a tangent-space normal map, read as data (linear).
        if (!map->is_map()) {
            params.fail("normal_map", "normal_map is a map {file: …, scale: …}");
        }
        Params keys(*map, params.what() + ".normal_map");
        Image image = read_image_keys(keys, context, false);
        const double scale = keys.number("scale", 1.0);
        if (!std::isfinite(scale)) {
            keys.fail("scale", "normal_map.scale must be a finite number");
        }
        keys.finish();
        try {
            mesh->set_normal_map(std::move(image), scale, std::move(tangents));
        } catch (const std::invalid_argument& e) {
            params.fail("normal_map", what + ": " + e.what());
        }
    }
    return mesh;
}

}  // namespace glint
