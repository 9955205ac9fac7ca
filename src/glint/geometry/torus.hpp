#pragma once

#include "glint/core/frame.hpp"
#include "glint/geometry/shape.hpp"

namespace glint {

// A ring torus: the points at distance `minor` from the circle of radius `major` around `center` in
// the plane perpendicular to `axis`. Closed: normals point out of the tube.
class Torus final : public Shape {
  public:
    // 0 < minor < major (create() reports anything else as a scene error).
    Torus(const Vec3& center, const Vec3& axis, double major, double minor);
    Bounds3 bounds() const override;
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    double area() const override { return 4 * kPi * kPi * major_ * minor_; }
    std::optional<ShapeSample> sample_area(Point2 u) const override;

    static std::unique_ptr<Shape> create(Params& params, const BuildContext& context);

  private:
    // The nearest t in (0, t_max), or kInf; `unit_point` is the hit in the torus's unit coordinates.
    double solve(const Ray& ray, double t_max, Vec3& unit_point) const;

    Vec3 center_;
    Frame frame_;  // frame_.n = axis
    double major_, minor_;
    // The quartic is solved in unit coordinates: centred, the axis as z, lengths divided by
    // major + minor (so the torus fits the unit sphere and the solver's tolerances are scale-free).
    double scale_;
    double unit_major_, unit_minor_;
};

}  // namespace glint
