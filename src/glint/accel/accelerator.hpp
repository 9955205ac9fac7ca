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
