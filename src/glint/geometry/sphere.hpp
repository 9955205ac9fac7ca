#pragma once

#include "glint/geometry/shape.hpp"

namespace glint {

class Sphere final : public Shape {
public:
    Sphere(const Vec3& center, double radius) : center_(center), radius_(radius) {}
    Bounds3 bounds() const override;
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    double area() const override { return 4 * kPi * radius_ * radius_; }
    std::optional<ShapeSample> sample_area(Point2 u) const override;
    const Vec3& center() const { return center_; }
    double radius() const { return radius_; }

    static std::unique_ptr<Shape> create(Params& params, const BuildContext& context);

private:
    // The roots t0 ≤ t1 of |O + tD − C|² = R², or false when the ray misses.
    bool solve(const Ray& ray, double& t0, double& t1) const;

    Vec3 center_;
    double radius_;
};

}  // namespace glint
