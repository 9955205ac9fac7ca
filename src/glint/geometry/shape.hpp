// Shapes (paper §V). A Shape answers where a ray first meets it; the accelerator decides which shapes
// to ask.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/bounds.hpp"
#include "glint/geometry/hit.hpp"
#include "glint/params/name_table.hpp"

namespace glint {

class Params;
struct BuildContext;

// A point chosen on a shape's surface, for lights with area.
struct ShapeSample {
    Vec3 point;
    Vec3 normal;          // unit, outward
    double pdf_area = 0;  // density per unit area
};

class Shape {
  public:
    virtual ~Shape() = default;

    // World bounds; infinite for unbounded shapes (planes), which accelerators keep aside.
    virtual Bounds3 bounds() const = 0;

    // The nearest intersection with t in (0, t_max). On a hit, fills `hit` (all but `primitive`) and
    // returns true; otherwise leaves `hit` untouched.
    virtual bool intersect(const Ray& ray, double t_max, Hit& hit) const = 0;

    // Whether any intersection has t in (0, t_max): shadow rays need no hit record.
    virtual bool occluded(const Ray& ray, double t_max) const {
        Hit unused;
        return intersect(ray, t_max, unused);
    }

    // Surface area, and a point uniformly distributed over it: what an area light needs of its shape.
    // Shapes that cannot be lights (unbounded ones) keep the defaults.
    virtual double area() const { return 0; }
    virtual std::optional<ShapeSample> sample_area(Point2 /*u*/) const { return std::nullopt; }
};

// The name → constructor table of shapes ("sphere", "plane", …). Each constructor reads its own
// parameters (Params records them, so unknown keys are caught by the caller).
using ShapeFactory = std::function<std::unique_ptr<Shape>(Params&, const BuildContext&)>;
struct ShapeEntry {
    std::string name;
    ShapeFactory create;
};
const NameTable<ShapeEntry>& shape_table();

}  // namespace glint
