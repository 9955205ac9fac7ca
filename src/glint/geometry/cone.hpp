#pragma once

#include "glint/geometry/axial.hpp"
#include "glint/geometry/shape.hpp"

namespace glint {

// A right circular cone from the centre of its base disk to its apex, open or capped (closed).
// Normals point away from the axis on the side, and out of the base cap.
class Cone final : public Shape {
  public:
    Cone(const Vec3& base, const Vec3& apex, double radius, bool capped);
    Bounds3 bounds() const override;
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    double area() const override;
    std::optional<ShapeSample> sample_area(Point2 u) const override;

    static std::unique_ptr<Shape> create(Params& params, const BuildContext& context);

  private:
    // The nearest t in (0, t_max) of the local ray, and whether it is on the base cap; kInf when none.
    double solve(const Ray& local, double t_max, bool& on_cap) const;
    double side_area() const { return kPi * radius_ * slant_; }

    AxialFrame axis_;  // local z from the base (0) to the apex (height)
    double radius_;
    double slant_;  // √(r² + h²), the length of the side from rim to apex
    bool capped_;
};

}  // namespace glint
