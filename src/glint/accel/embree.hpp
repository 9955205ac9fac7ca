// The Embree 3 backend (built only when CMake finds Embree: GLINT_HAVE_EMBREE). Behind the same
// Accelerator interface as the BVH, so that the two can be checked against each other and raced.
//
// Mesh triangles go to Embree as RTC_GEOMETRY_TYPE_TRIANGLE (float); every other bounded shape is a
// user geometry whose callbacks call the shape in double. Embree's candidate triangle hits are checked
// in double by a filter before Embree accepts them, and the nearest is recomputed in double by the
// mesh, so the answers are the double-precision ones, as with the BVH. Unbounded shapes (planes) are
// tested apart, as in the BVH.
#pragma once

#ifdef GLINT_HAVE_EMBREE

#include <embree3/rtcore.h>

#include "glint/accel/accelerator.hpp"

namespace glint {

class Mesh;

class EmbreeAccelerator final : public Accelerator {
  public:
    explicit EmbreeAccelerator(std::span<const Shape* const> shapes);
    ~EmbreeAccelerator() override;
    EmbreeAccelerator(const EmbreeAccelerator&) = delete;
    EmbreeAccelerator& operator=(const EmbreeAccelerator&) = delete;

    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    Bounds3 bounds() const override { return bounds_; }

  private:
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::vector<const Shape*> shapes_;      // by scene index = Embree geometry id
    std::vector<const Mesh*> meshes_;       // shapes_[i] as a mesh, or nullptr
    std::vector<std::uint32_t> unbounded_;  // scene indices of planes and other infinite shapes
    Bounds3 bounds_;
};

}  // namespace glint

#endif
