// The Embree 3 backend (built only when CMake finds Embree: GLINT_HAVE_EMBREE). Behind the same
// Accelerator interface as the BVH, so that the two can be checked against each other and raced.
//
// Mesh triangles go to Embree as RTC_GEOMETRY_TYPE_TRIANGLE (float); every other bounded shape is a
// user geometry whose callbacks call the shape in double. Embree's candidate triangle hits are checked
// in double by a filter before Embree accepts them, and the nearest is recomputed in double by the
// mesh, so the answers are the double-precision ones, as with the BVH. Unbounded shapes (planes) are
// tested apart, as in the BVH; so are shapes with a coordinate beyond kEmbreeLargest, which Embree
// would silently leave out of its scene; and rays from beyond it, which Embree cannot trace, are tested
// against every shape.
#pragma once

#ifdef GLINT_HAVE_EMBREE

#include <embree3/rtcore.h>

#include <string>

#include "glint/accel/accelerator.hpp"

namespace glint {

class Mesh;

class EmbreeAccelerator final : public Accelerator {
  public:
    // Embree ignores primitives with a coordinate beyond this ("values greater than 1.844E18f", its
    // rtcCommitScene documentation), so a shape whose box reaches beyond it is not given to Embree.
    static constexpr double kEmbreeLargest = 1.844e18;

    // `device_config`: Embree's device configuration string (rtcNewDevice), empty for its defaults. Embree
    // picks the widest instruction set it was built for that the CPU has (AVX-512 on such CPUs, with
    // Debian's Embree); "isa=avx2" holds it to AVX2, glint's own traversal's (bench/accel.cpp races both).
    explicit EmbreeAccelerator(std::span<const Shape* const> shapes, const std::string& device_config = "");
    ~EmbreeAccelerator() override;
    EmbreeAccelerator(const EmbreeAccelerator&) = delete;
    EmbreeAccelerator& operator=(const EmbreeAccelerator&) = delete;

    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    Bounds3 bounds() const override { return bounds_; }

  private:
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::vector<const Shape*> shapes_;  // by scene index = Embree geometry id
    std::vector<const Mesh*> meshes_;   // shapes_[i] as a mesh, or nullptr
    // Scene indices of the shapes tested for every ray, apart from Embree: planes and other infinite
    // shapes, and shapes beyond kEmbreeLargest.
    std::vector<std::uint32_t> direct_;
    // Scene indices of the shapes given to Embree: tested one by one for a ray Embree cannot trace (one
    // from beyond kEmbreeLargest).
    std::vector<std::uint32_t> traced_;
    Bounds3 bounds_;
};

}  // namespace glint

#endif
