// Shapes (paper §V). A Shape answers where a ray first meets it; the accelerator decides which shapes
// to ask.
#pragma once

#include <functional>
#include <limits>
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

// A point chosen on a shape as seen from a reference point: what a light with area needs to light it.
struct SeenSample {
    Vec3 point;
    Vec3 normal;                 // unit, outward
    Vec3 wi;                     // unit, from the reference point towards `point`
    double pdf_solid_angle = 0;  // density of wi per steradian at the reference point
};

// A point sampled by area, `s`, as seen from `ref`: its density converted to solid angle by
// distance² / |cos θ| at the point (the default Shape::sample_seen_from). Nothing when the point is `ref`
// or is seen edge-on. Inline, so that a light that knows its shape's type (AreaLight with a rectangle)
// pays no call for it.
inline std::optional<SeenSample> seen_from(const Vec3& ref, const ShapeSample& s) {
    const Vec3 to_point = s.point - ref;
    const double d2 = length_squared(to_point);
    // Also nothing when d² is subnormal or infinite, where 1/d² would not be finite.
    if (!(d2 >= std::numeric_limits<double>::min() && d2 <= std::numeric_limits<double>::max())) {
        return std::nullopt;
    }
    // An area dA at distance d, seen at angle θ to its normal, spans dω = |cos θ| dA / d², so the
    // density is pdf_area d² / |cos θ| = pdf_area d³ / |n · (point − ref)|. Written so, the square root,
    // 1/d² and that division run side by side, where 1/√(d²) waited for the square root and |n · wi|
    // and its division for both: the shadow ray's checks wait less (the Cornell box in 0.978 of the
    // time, bench/ab.py).
    const double d = std::sqrt(d2);
    const double inverse_d2 = 1 / d2;
    const double projected = std::abs(dot(s.normal, to_point));  // d |cos θ|
    if (projected == 0) {
        return std::nullopt;
    }
    const Vec3 wi = to_point * (d * inverse_d2);
    return SeenSample{s.point, s.normal, wi, s.pdf_area * d2 / projected * d};
}

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

    // A point of the surface for the reference point `ref` to look at, with the solid-angle density of
    // the direction towards it (pbrt-v4's Shape::Sample(ctx, u)). A shape may favour what `ref` can see:
    // a sphere samples the cone it subtends. The default is sample_area() converted to solid angle, by
    // distance² / |cos θ| at the sampled point. Nothing when the sample is degenerate (at `ref`, or seen
    // edge-on) or the shape cannot be sampled.
    virtual std::optional<SeenSample> sample_seen_from(const Vec3& ref, Point2 u) const;

    // The density with which sample_seen_from(ref, ·) returns the unit direction wi, whose ray from ref
    // first meets this shape at `on_shape` (its point and outward normal, as intersect() gives them).
    virtual double pdf_seen_from(const Vec3& ref, const Vec3& wi, const Hit& on_shape) const;

    // Whether sample_seen_from() is the default: sample_area() converted to solid angle, uniform by area
    // whatever the reference point. An Instance keeps such shapes on uniform area sampling in world space.
    virtual bool samples_by_area() const { return true; }
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
