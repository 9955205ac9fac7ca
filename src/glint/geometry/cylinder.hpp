#pragma once

#include "glint/geometry/axial.hpp"
#include "glint/geometry/shape.hpp"

namespace glint {

// A circular cylinder from the centre of its base to the centre of its top, open (a tube) or capped
// (closed). Normals point away from the axis on the side, and out of the caps.
class Cylinder final : public Shape {
  public:
    Cylinder(const Vec3& base, const Vec3& top, double radius, bool capped);
    Bounds3 bounds() const override;
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    double area() const override;
    std::optional<ShapeSample> sample_area(Point2 u) const override;

    static std::unique_ptr<Shape> create(Params& params, const BuildContext& context);

  private:
    enum class Part { Side, Base, Top };
    // The nearest t in (0, t_max) of the local ray, and the part hit; kInf when none.
    double solve(const Ray& local, double t_max, Part& part) const;

    AxialFrame axis_;
    double radius_;
    bool capped_;
};

}  // namespace glint
