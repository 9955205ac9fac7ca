#pragma once

#include "glint/core/frame.hpp"
#include "glint/geometry/shape.hpp"

namespace glint {

// A flat disk, or an annulus (a disk with a round hole) when inner_radius > 0. One-sided geometry,
// two-sided for shading: `normal` is the side the user gave.
class Disk final : public Shape {
  public:
    Disk(const Vec3& center, const Vec3& normal, double radius, double inner_radius = 0);
    Bounds3 bounds() const override;
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    double area() const override { return kPi * (radius_ * radius_ - inner_radius_ * inner_radius_); }
    std::optional<ShapeSample> sample_area(Point2 u) const override;

    // {type: disk} and {type: annulus}: the same shape, two sets of keys.
    static std::unique_ptr<Shape> create(Params& params, const BuildContext& context);
    static std::unique_ptr<Shape> create_annulus(Params& params, const BuildContext& context);

  private:
    // t of the hit within (0, t_max) and inside the ring, or kInf when there is none.
    double solve(const Ray& ray, double t_max, Vec3& point) const;

    Vec3 center_;
    Frame frame_;  // frame_.n is the unit normal; s and t give the angle of uv
    double radius_, inner_radius_;
};

}  // namespace glint
