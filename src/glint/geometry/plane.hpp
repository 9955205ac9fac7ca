#pragma once

#include "glint/geometry/shape.hpp"

namespace glint {

// The infinite plane through `point` with unit `normal`.
class Plane final : public Shape {
public:
    Plane(const Vec3& point, const Vec3& normal);
    Bounds3 bounds() const override { return Bounds3::infinite(); }
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;

    static std::unique_ptr<Shape> create(Params& params, const BuildContext& context);

private:
    double solve(const Ray& ray) const;

    Vec3 point_;
    Vec3 normal_;
    Vec3 tangent_, bitangent_;  // for uv
};

}  // namespace glint
