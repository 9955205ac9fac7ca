#pragma once

#include "glint/accel/accelerator.hpp"
#include "glint/accel/wide_bvh.hpp"

namespace glint {

// The scene's BVH: an 8-wide BVH (accel/wide_bvh.hpp) whose leaves are the scene's bounded shapes,
// called virtually (a mesh is one such leaf, with its own BVH inside: a two-level hierarchy).
// Unbounded shapes (planes) have no box to sort, so they are kept aside and tested for every ray.
class BvhAccelerator final : public Accelerator {
  public:
    explicit BvhAccelerator(std::span<const Shape* const> shapes);
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    Bounds3 bounds() const override { return bounds_; }

    const WideBvh& bvh() const { return bvh_; }
    std::size_t unbounded_count() const { return unbounded_.size(); }
    double build_seconds() const { return build_seconds_; }

  private:
    std::vector<const Shape*> shapes_;        // in BVH leaf order
    std::vector<std::uint32_t> shape_index_;  // the scene's index of shapes_[i]
    std::vector<std::uint32_t> unbounded_;    // scene indices of shapes with infinite bounds
    std::vector<const Shape*> all_;           // every shape, by scene index
    WideBvh bvh_;
    Bounds3 bounds_;
    double build_seconds_ = 0;
};

}  // namespace glint
