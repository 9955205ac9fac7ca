#pragma once

#include "glint/geometry/shape.hpp"

namespace glint {

// The parallelogram {corner + a·edge1 + b·edge2 : a, b in [0, 1]}. One-sided geometry, two-sided for
// shading: the normal is edge1 × edge2 normalised (right-hand rule).
class Rectangle final : public Shape {
  public:
    // The edges must not be parallel or zero (create() reports that as a scene error).
    Rectangle(const Vec3& corner, const Vec3& edge1, const Vec3& edge2);
    Bounds3 bounds() const override;
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    double area() const override { return area_; }
    std::optional<ShapeSample> sample_area(Point2 u) const override { return point_at(u); }
    // sample_area() without the virtual call and the optional, for AreaLight.
    ShapeSample point_at(Point2 u) const {
        // An affine map of the unit square: uniform in (a, b) is uniform by area.
        return {corner_ + u.x * edge1_ + u.y * edge2_, normal_, pdf_area_};
    }

    static std::unique_ptr<Shape> create(Params& params, const BuildContext& context);

    // What solve() reads, for the scene's flat list, which repeats solve() four rectangles at a time
    // (accel/bvh.cpp).
    const Vec3& corner() const { return corner_; }
    const Vec3& normal() const { return normal_; }
    const Vec3& dual1() const { return dual1_; }
    const Vec3& dual2() const { return dual2_; }
    // The Hit of a hit at t, whose point and (a, b) solve() found (or the flat list's four-at-a-time
    // repetition of it): what intersect() records.
    void fill_hit(double t, const Vec3& point, Point2 ab, Hit& hit) const;

  private:
    // t of the hit within (0, t_max) and inside the parallelogram, or kInf; `ab` are its (a, b).
    double solve(const Ray& ray, double t_max, Vec3& point, Point2& ab) const;

    Vec3 corner_, edge1_, edge2_;
    Vec3 normal_;  // unit
    // Dual vectors: for q in the plane, q = a·edge1 + b·edge2 with a = q·dual1, b = q·dual2.
    Vec3 dual1_, dual2_;
    double area_;
    double pdf_area_;  // 1 / area_, not divided per sample
};

}  // namespace glint
