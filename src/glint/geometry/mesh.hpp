#pragma once

#include <array>
#include <memory>
#include <span>
#include <vector>

#include "glint/bvh/wide_bvh.hpp"
#include "glint/core/uninitialized_allocator.hpp"
#include "glint/geometry/mesh_io/mesh_data.hpp"
#include "glint/geometry/shape.hpp"
#include "glint/geometry/triangle_block.hpp"
#include "glint/image/image.hpp"

namespace glint {

// A triangle mesh: one Shape with its own BVH over its triangles (so the scene's BVH sees one leaf,
// and an instance of the mesh shares this BVH). Triangles are tested with the watertight test of
// geometry/triangle.hpp in double precision, from flat arrays. Vertex normals, when the file has them,
// are interpolated for shading (hit.element is the index of the triangle hit).
class Mesh final : public Shape {
  public:
    // Takes a loaded mesh: drops zero-area triangles, recomputes missing or broken (zero, NaN) vertex
    // normals from the surrounding faces, and builds the BVH. Throws std::invalid_argument if no
    // triangle has an area, or if the data is not a mesh: an index out of range, a position that is not
    // finite, normals neither one per position nor none, more triangles than MeshLimits allows.
    // (Positions beyond float's range, which the loaders reject, are accepted here: the BVH bounds
    // them with infinite boxes, which are correct but cull nothing.)
    explicit Mesh(MeshData data);
    // Not copyable: the BVH prefetches from this mesh's own triangle blocks (WideBvh::set_leaf_data), so
    // a copy would point into the original's. Moving keeps the blocks' storage, and the pointer valid.
    Mesh(const Mesh&) = delete;
    Mesh& operator=(const Mesh&) = delete;
    Mesh(Mesh&&) = default;
    Mesh& operator=(Mesh&&) = default;

    Bounds3 bounds() const override { return bvh_.bounds(); }
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    double area() const override { return area_cdf_.empty() ? 0 : area_cdf_.back(); }
    std::optional<ShapeSample> sample_area(Point2 u) const override;

    // Tests the single triangle `index` (what the Embree backend calls to check and redo its hits in
    // double): with the hit's details, or only whether it is hit at t in (0, t_max).
    bool intersect_triangle(std::uint32_t index, const Ray& ray, double t_max, Hit& hit) const;
    bool hits_triangle(std::uint32_t index, const Ray& ray, double t_max) const;

    // For other backends and statistics. Triangles are in BVH order; hit.element indexes this list.
    std::span<const Vec3> positions() const { return positions_; }
    std::span<const std::array<std::uint32_t, 3>> triangles() const { return triangles_; }
    const WideBvh& bvh() const { return bvh_; }
    double build_seconds() const { return build_seconds_; }
    std::size_t memory_bytes() const;

    // A tangent-space normal map over the mesh's uvs (glTF's normalTexture): each texel (r, g, b) in
    // [0, 1] is the normal (2r − 1, 2g − 1, 2b − 1) in the frame (tangent, bitangent, normal) at the hit,
    // x and y multiplied by `scale`. `tangents`, one per vertex, are the mesh data's (glTF's TANGENT,
    // MeshData::tangents); when empty they are computed from the uvs (tangents_from_uvs in mesh.cpp).
    // Throws std::invalid_argument if the mesh has no uvs, or tangents not one per vertex.
    void set_normal_map(Image image, double scale, std::vector<std::array<double, 4>> tangents = {});

    // {type: mesh, file: name.obj | name.ply}; the file is found relative to the scene file.
    static std::unique_ptr<Shape> create(Params& params, const BuildContext& context);

  private:
    // The hit on triangle `index`, whose vertices are p0, p1, p2 (the caller passes them because it
    // may have them at hand: the BVH path reads them from the triangle block it has just tested, which
    // is in cache, instead of going through triangles_ and positions_, two more memory round trips).
    void fill_hit(std::uint32_t index, const Vec3& p0, const Vec3& p1, const Vec3& p2, const TriangleHit& at,
                  Hit& hit) const;
    // The shading normal of a hit on a normal-mapped mesh, once fill_hit has written the rest.
    void map_normal(std::uint32_t index, const TriangleHit& at, Hit& hit) const;

    struct NormalMap {
        Image image;   // read linear: texels are data, not colour
        double scale;  // glTF's normalTexture.scale
    };

    std::vector<Vec3> positions_;
    std::vector<Vec3> normals_;  // empty (flat shading) or one unit (or zero: use the face) per position
    std::vector<Point2> uvs_;    // empty (a hit's uv is its barycentric (b1, b2)) or one per position
    std::vector<std::array<std::uint32_t, 3>> triangles_;
    // Only with a normal map (set_normal_map): the map, and per vertex a unit tangent and the
    // handedness w (±1) of the bitangent w · normal × tangent. Null and empty otherwise, so that a mesh
    // without one pays nothing but a test of the pointer per hit.
    std::unique_ptr<const NormalMap> normal_map_;
    std::vector<std::array<double, 4>> tangents_;
    // The leaves' triangles, four to a block, with their vertices copied in: what the hot loop reads.
    // A BVH leaf of n triangles is ⌈n/4⌉ consecutive blocks starting at its `first`.
    std::vector<TriangleBlock, UninitializedAllocator<TriangleBlock>> blocks_;  // filled in parallel
    std::vector<double> area_cdf_;  // running sum of triangle areas, for sample_area
    WideBvh bvh_;
    double build_seconds_ = 0;
};

}  // namespace glint
