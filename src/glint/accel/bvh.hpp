#pragma once

#include "glint/accel/accelerator.hpp"
#include "glint/bvh/wide_bvh.hpp"

namespace glint {

// The scene's BVH: an 8-wide BVH (bvh/wide_bvh.hpp) whose leaves are the scene's bounded shapes,
// called virtually (a mesh is one such leaf, with its own BVH inside: a two-level hierarchy).
// Unbounded shapes (planes) have no box to sort, so they are kept aside and tested for every ray; so is
// a lone bounded shape (a scene of one mesh), for which a tree of one leaf would only add a traversal.
class BvhAccelerator final : public Accelerator {
  public:
    explicit BvhAccelerator(std::span<const Shape* const> shapes);
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    Bounds3 bounds() const override { return bounds_; }
    // The box of the bounded shapes alone (bounds() is infinite as soon as there is a plane).
    const Bounds3& bounded_bounds() const { return bounded_bounds_; }

    const WideBvh& bvh() const { return bvh_; }
    std::size_t unbounded_count() const { return unbounded_count_; }
    double build_seconds() const { return build_seconds_; }

  private:
    // Spheres are tested in the leaves directly, from this flat copy (no virtual call per sphere, and
    // the hit's normal and uv are computed once, for the nearest); radius 0 marks any other shape.
    struct LeafSphere {
        Vec3 center;
        double radius = 0;
    };

    std::vector<const Shape*> shapes_;        // in BVH leaf order
    std::vector<LeafSphere> leaf_spheres_;    // in BVH leaf order
    std::vector<std::uint32_t> shape_index_;  // the scene's index of shapes_[i]
    std::vector<std::uint32_t> direct_;       // scene indices of the shapes tested for every ray
    std::size_t unbounded_count_ = 0;         // how many of them have infinite bounds
    std::vector<const Shape*> all_;           // every shape, by scene index
    WideBvh bvh_;
    Bounds3 bounds_;
    Bounds3 bounded_bounds_;
    double build_seconds_ = 0;
};

}  // namespace glint
