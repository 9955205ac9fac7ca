#pragma once

#include "glint/accel/accelerator.hpp"
#include "glint/bvh/wide_bvh.hpp"

namespace glint {

// The scene's BVH: an 8-wide BVH (bvh/wide_bvh.hpp) whose leaves are the scene's bounded shapes,
// called virtually (a mesh is one such leaf, with its own BVH inside: a two-level hierarchy; a scene
// of one mesh alone goes straight to the mesh's BVH).
// Unbounded shapes (planes) have no box to sort, so they are kept aside and tested for every ray; so are
// all the bounded shapes of a scene of at most kFlatMaxShapes (smallpt's nine spheres), for which a
// traversal costs more than the tests it would save. Either way the answers are the same
// bits: the nearest hit's shape computes its Hit; only exact ties in t between two shapes may go to
// either.
class BvhAccelerator final : public Accelerator {
  public:
    // Measured (random rays against random spheres, and renders): spheres alone, the flat test wins up
    // to 8 to 10 of them (smallpt's nine: 11 % less render time); a Cornell box's 16 rectangles, whose
    // tests are virtual calls, render 26 % slower flat than with the tree.
    static constexpr std::size_t kFlatMaxShapes = 9;

    // `flat_max_shapes`: up to how many bounded shapes are tested without a tree (tests vary it).
    explicit BvhAccelerator(std::span<const Shape* const> shapes,
                            std::size_t flat_max_shapes = kFlatMaxShapes);
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    // A tree of spheres with nothing outside it (RTIOW's scenes) is traced in packets of up to
    // WideBvh::kMaxPacket rays, each sphere tested against four rays at once in AVX2 lanes; any other
    // scene one ray at a time. Either way each ray gets intersect's bits: a ray of a packet that met
    // two spheres at the same t is traced again alone.
    void intersect_packet(const Ray* const* rays, int n, double t_max, Hit* const* hits,
                          bool* found) const override;
    bool traces_packets() const override;
    Bounds3 bounds() const override { return bounds_; }
    // The box of the bounded shapes alone (bounds() is infinite as soon as there is a plane).
    const Bounds3& bounded_bounds() const { return bounded_bounds_; }

    const WideBvh& bvh() const { return bvh_; }
    std::size_t unbounded_count() const { return unbounded_count_; }
    // How many shapes are tested for every ray, outside the tree: the unbounded ones, and the bounded
    // ones too when they are few.
    std::size_t flat_count() const { return direct_.size(); }
    double build_seconds() const { return build_seconds_; }

  private:
    // Spheres are tested from a flat copy of their centre and radius (no virtual call per sphere, and
    // the hit's normal is computed once, for the nearest); radius 0 marks any other shape. 32 bytes,
    // one AVX2 register: four consecutive records are tested at once (bvh.cpp).
    struct LeafSphere {
        Vec3 center;
        double radius = 0;
    };
    static_assert(sizeof(LeafSphere) == 4 * sizeof(double));
    // Shapes in the order they are tested, in parallel arrays: the leaves read `spheres` most, so it
    // stays 32 bytes an entry. `spheres` has kSpherePadding more records than there are shapes (radius
    // 0, never tested), so that four records can be read from any entry.
    static constexpr std::size_t kSpherePadding = 3;
    // The flat list's rectangles, field by field, four entries a block (block g holds entries 4g to
    // 4g + 3): tested four at a time with AVX2, as Rectangle::solve would test each. Lanes of other
    // shapes hold zeros and are never read.
    struct alignas(32) RectangleBlock {
        double corner[3][4] = {}, normal[3][4] = {}, dual1[3][4] = {}, dual2[3][4] = {};
        // The culling boxes (culling_boxes) of the block's shapes, every lane its shape's (padding lanes
        // zeros), tested four at a time; only the answers of the other shapes' lanes are kept.
        double box_lo[3][4] = {}, box_hi[3][4] = {};
        unsigned rectangles = 0;  // the lanes (bit i for entry 4g + i) that are rectangles
        unsigned spheres = 0;     // and those that are spheres (a block without any skips their test)
    };
    struct ShapeList {
        std::vector<LeafSphere> spheres = std::vector<LeafSphere>(kSpherePadding);
        std::vector<const Shape*> shapes;
        std::vector<std::uint32_t> scene_index;
        std::vector<RectangleBlock> rectangles;  // only in a list made with_rectangles (the flat one)
        // The flat list's boxes of its shapes, padded (empty in the tree's list, whose traversal has
        // tested them): a shape tested by a virtual call (an instanced box, a mesh) is skipped when the
        // ray misses its box, which costs a few multiplications instead of its own test.
        std::vector<Bounds3> culling_boxes;
        bool with_rectangles = false;
        // The flat list tests four at a time only when it has a few spheres and rectangles.
        std::size_t sphere_count = 0;
        std::size_t rectangle_count = 0;
        void add(const Shape* shape, std::uint32_t index);
        std::size_t size() const { return shapes.size(); }
        // Every shape a sphere: four at a time needs no block (read for the flat list only).
        bool spheres_only() const { return sphere_count == size(); }
    };

    // The body of intersect and occluded, with the spheres (and rectangles) of the flat list tested one at a
    // time (kFourSpheres false) or four at a time with AVX2 (true). Both are reached through intersect_avx2
    // and occluded_avx2 when the CPU has AVX2 and FMA; intersect_with<false> also through the
    // *_one_at_a_time functions without. Both give the same bits. Tree leaves are tested one at a time
    // either way (bvh.cpp says why).
    template <bool kFourSpheres>
    bool intersect_with(const Ray& ray, double t_max, Hit& hit) const;
    template <bool kFourSpheres>
    bool occluded_with(const Ray& ray, double t_max) const;
    // The ray's reciprocal direction for the flat list's box tests (zero when the list has none).
    Vec3 culling_inverse(const Ray& ray) const;
    // Every ray's entry when the CPU has AVX2, the flat list four at a time or not: compiled for AVX2 and
    // FMA (the tree's traversal's target) and flattened, so that one function holds the flat list, the
    // traversal and the leaf tests; the shapes' own (virtual) tests and the filling of the nearest hit
    // stay calls (bvh.cpp gives the figures).
    template <bool kFourSpheres>
    bool intersect_avx2(const Ray& ray, double t_max, Hit& hit) const;
    template <bool kFourSpheres>
    bool occluded_avx2(const Ray& ray, double t_max) const;
    // intersect_with<false> and occluded_with<false> without AVX2 (the CPU lacks it, or a test forced the
    // scalar traversal), kept out of line so that intersect() stays a small dispatch.
    bool intersect_one_at_a_time(const Ray& ray, double t_max, Hit& hit) const;
    bool occluded_one_at_a_time(const Ray& ray, double t_max) const;
    // intersect_packet for at most WideBvh::kMaxPacket rays, when packet_traversal_.
    void intersect_packet_avx2(const Ray* const* rays, int n, double t_max, Hit* const* hits,
                               bool* found) const;

    ShapeList leaves_;                 // the tree's, in its leaf order
    ShapeList direct_;                 // tested for every ray: unbounded first, then by scene index
    std::size_t unbounded_count_ = 0;  // how many of direct_ have infinite bounds
    WideBvh bvh_;
    Bounds3 bounds_;
    Bounds3 bounded_bounds_;

    // A scene of one mesh and nothing else: every ray goes straight to the mesh's own tree, without
    // the flat list's set-up (its reciprocals, the mesh's culling box, which the tree's root node
    // tests again). Null otherwise. (A flat list that skips what it does not need, with no box and no
    // sphere, still cost a lone mesh's rays 3 % more than this: the loop and the state of its
    // flattened function. docs/benchmarks.md has the figures.)
    const Shape* lone_mesh_ = nullptr;
    std::uint32_t lone_mesh_index_ = 0;  // its scene index
    double build_seconds_ = 0;
    bool packet_traversal_ = false;  // intersect_packet traces packets (see the constructor)
};

}  // namespace glint
