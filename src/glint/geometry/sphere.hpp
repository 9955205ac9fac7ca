#pragma once

#include <cmath>
#include <utility>

#include "glint/geometry/shape.hpp"

namespace glint {

// 1 / |D|² of a ray's direction D, which the sphere tests multiply by where they would divide by |D|²:
// computed once a ray by the scene's BVH, which may test several spheres with it: two divisions fewer a
// test (smallpt's scene, nine spheres four at a time: 2 % of the render's time). A direction shorter than
// about 1e-154, whose |D|² is below 1 / DBL_MAX, makes this infinite and misses every sphere (dividing
// missed them below about 1e-162); no ray of a render is that short.
inline double inverse_length_squared(const Vec3& direction) {
    return 1 / dot(direction, direction);
}

// The roots t0 ≤ t1 of |O + tD − C|² = R², or false when the ray misses; `inverse_a` is
// inverse_length_squared(ray.direction). Inline so that the scene's BVH can test spheres in its leaves
// without a virtual call.
inline bool sphere_roots(const Vec3& center, double radius, const Ray& ray, double inverse_a, double& t0,
                         double& t1) {
    // |O + tD − C|² = R² with oc = O − C: a t² + 2 h t + c = 0, h = D·oc (the "half b" form, errata §5.1).
    const Vec3 oc = ray.origin - center;
    const double a = dot(ray.direction, ray.direction);
    const double h = dot(ray.direction, oc);
    const double c = dot(oc, oc) - radius * radius;
    // From outside or on the sphere (c ≥ 0) and going away from its centre (h > 0), both roots are
    // negative: q below has the sign of −h, and c / q that of q. Answered here, before the square root
    // and the division, which would find the same: every ray leaving a sphere's surface meets this test
    // again in the sphere's leaf (bench/ab.py: RTIOW's final scene in 0.970 of the time).
    if (h > 0 && c >= 0) {
        return false;
    }
    // h² − a c loses every digit when the sphere is small or far (h² ≈ a c). Written as
    // a (R² − |l|²), with l the offset from C to the line's closest point, it keeps them (pbrt-v4 §6.8).
    const Vec3 l = oc - (h * inverse_a) * ray.direction;
    const double discriminant = a * (radius * radius - dot(l, l));
    if (discriminant < 0) {
        return false;
    }
    // q = −(h + sign(h)·√Δ) never subtracts nearly equal numbers; the roots are q/a and c/q.
    const double q = -(h + std::copysign(std::sqrt(discriminant), h));
    if (q == 0) {
        return false;  // a = c = h = 0 cannot happen for a real ray; q = 0 means a degenerate ray
    }
    t0 = q * inverse_a;
    t1 = c / q;
    if (t0 > t1) {
        std::swap(t0, t1);
    }
    return true;
}

// The t at which the ray meets the sphere in (0, t_max): the near root, or the far one from inside.
inline bool sphere_hit_t(const Vec3& center, double radius, const Ray& ray, double inverse_a, double t_max,
                         double& t) {
    double t0 = 0;
    double t1 = 0;
    if (!sphere_roots(center, radius, ray, inverse_a, t0, t1)) {
        return false;
    }
    t = t0 > 0 ? t0 : t1;
    return t > 0 && t < t_max;
}

// Whether the ray meets the sphere in (0, t_max). (A root in range exists exactly when sphere_hit_t
// finds one: t0 ≤ t1, so when t0 > 0 is beyond t_max, t1 is too.)
inline bool sphere_occludes(const Vec3& center, double radius, const Ray& ray, double inverse_a,
                            double t_max) {
    double t = 0;
    return sphere_hit_t(center, radius, ray, inverse_a, t_max, t);
}

class Sphere final : public Shape {
  public:
    Sphere(const Vec3& center, double radius)
        : center_(center), radius_(radius), inverse_radius_(1 / radius) {}
    Bounds3 bounds() const override;
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    // What intersect records for the hit at t, a root that sphere_hit_t found: for the scene's BVH,
    // which tests spheres inline and fills the nearest one's Hit without solving for t again.
    void fill_hit(const Ray& ray, double t, Hit& hit) const;
    double area() const override { return 4 * kPi * radius_ * radius_; }
    std::optional<ShapeSample> sample_area(Point2 u) const override;
    // Seen from outside, uniformly over the cone of directions the sphere subtends (pbrt-v4 §6.2.4): no
    // sample lands on the far side, and the density is one constant. From inside (or on the surface),
    // by area, as every shape.
    std::optional<SeenSample> sample_seen_from(const Vec3& ref, Point2 u) const override;
    double pdf_seen_from(const Vec3& ref, const Vec3& wi, const Hit& on_shape) const override;
    // The same for the point `point` of outward normal `normal`, all it reads of the Hit: for callers
    // that have no Hit record, to spare them building one (LightVisibility's mixture density).
    double pdf_seen_from(const Vec3& ref, const Vec3& wi, const Vec3& point, const Vec3& normal) const;
    bool samples_by_area() const override { return false; }
    const Vec3& center() const { return center_; }
    double radius() const { return radius_; }

    static std::unique_ptr<Shape> create(Params& params, const BuildContext& context);

  private:
    // Whether `ref` is outside, where the cone sampling applies.
    bool seen_from_outside(const Vec3& ref) const;
    // The cone sampling's density (per steradian) from `ref` outside.
    double cone_pdf(const Vec3& ref) const;

    Vec3 center_;
    double radius_;
    double inverse_radius_;  // for fill_hit's normal, without a division
};

}  // namespace glint
