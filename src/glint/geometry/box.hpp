#pragma once

#include "glint/geometry/shape.hpp"

namespace glint {

// An axis-aligned box, closed: normals point outwards, also for rays from inside (they hit the face
// they leave through). Rotated boxes are boxes with a `transform`.
class Box final : public Shape {
  public:
    Box(const Vec3& min, const Vec3& max)
        : min_(min), max_(max), max_abs_corner_(std::max(max_component(abs(min)), max_component(abs(max)))) {}
    Bounds3 bounds() const override { return {min_, max_}; }
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    // intersect(), telling also the face hit (0–2: the min faces of x, y, z; 3–5: their max faces), so
    // that an Instance can take the face's world normal from a table instead of transforming it per hit.
    bool intersect_face(const Ray& ray, double t_max, Hit& hit, int& face) const;
    bool occluded(const Ray& ray, double t_max) const override;
    double area() const override;
    std::optional<ShapeSample> sample_area(Point2 u) const override;

    static std::unique_ptr<Shape> create(Params& params, const BuildContext& context);

  private:
    // The nearest t in (0, t_max) and the face it is on (axis 0–2, side −1 or +1), or kInf.
    double solve(const Ray& ray, double t_max, int& axis, int& side) const;

    Vec3 min_, max_;
    double max_abs_corner_;  // the largest coordinate magnitude of the box, for the hits' error bound
};

}  // namespace glint
