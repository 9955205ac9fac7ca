// Finds the nearest primitive a ray hits. Implementations: a linear list (the brute-force reference),
// and the BVH and Embree backends of the geometry issue, all behind this interface.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "glint/geometry/shape.hpp"
#include "glint/params/name_table.hpp"

namespace glint {

class Accelerator {
  public:
    virtual ~Accelerator() = default;
    // Nearest hit with t in (0, t_max); sets hit.primitive to the index of the shape in the list given
    // at construction.
    virtual bool intersect(const Ray& ray, double t_max, Hit& hit) const = 0;
    // The nearest hits of n rays, as n calls of intersect would find them (found[k] for ray k); a
    // backend may trace them together (rays that go the same way, such as a pixel's camera rays).
    virtual void intersect_packet(const Ray* const* rays, int n, double t_max, Hit* const* hits,
                                  bool* found) const {
        for (int k = 0; k < n; ++k) {
            found[k] = intersect(*rays[k], t_max, *hits[k]);
        }
    }
    // Whether intersect_packet traces its rays together rather than one after the other: only then is
    // it worth a caller's while to gather rays it would otherwise trace as they come.
    virtual bool traces_packets() const { return false; }
    // Any hit with t in (0, t_max).
    virtual bool occluded(const Ray& ray, double t_max) const = 0;
    virtual Bounds3 bounds() const = 0;
};

// The name → constructor table of accelerators. The shapes outlive the accelerator.
using AcceleratorFactory = std::function<std::unique_ptr<Accelerator>(std::span<const Shape* const> shapes)>;
struct AcceleratorEntry {
    std::string name;
    std::string summary;
    AcceleratorFactory create;
};
const NameTable<AcceleratorEntry>& accelerator_table();
std::unique_ptr<Accelerator> make_accelerator(const std::string& name, std::span<const Shape* const> shapes);

}  // namespace glint
