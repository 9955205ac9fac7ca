// Sphere {type: sphere, center: [x, y, z], radius: r}.
#include "glint/geometry/sphere.hpp"

#include "glint/scene/params.hpp"

namespace glint {

Bounds3 Sphere::bounds() const {
    const Vec3 r{radius_, radius_, radius_};
    return {center_ - r, center_ + r};
}

bool Sphere::solve(const Ray& ray, double& t0, double& t1) const {
    // |O + tD − C|² = R² with oc = O − C: a t² + 2 h t + c = 0, h = D·oc (the "half b" form, errata §5.1).
    const Vec3 oc = ray.origin - center_;
    const double a = dot(ray.direction, ray.direction);
    const double h = dot(ray.direction, oc);
    const double c = dot(oc, oc) - radius_ * radius_;
    // h² − a c loses every digit when the sphere is small or far (h² ≈ a c). Written as
    // a (R² − |l|²), with l the offset from C to the line's closest point, it keeps them (pbrt-v4 §6.8).
    const Vec3 l = oc - (h / a) * ray.direction;
    const double discriminant = a * (radius_ * radius_ - dot(l, l));
    if (discriminant < 0) {
        return false;
    }
    // q = −(h + sign(h)·√Δ) never subtracts nearly equal numbers; the roots are q/a and c/q.
    const double q = -(h + std::copysign(std::sqrt(discriminant), h));
    if (q == 0) {
        return false;  // a = c = h = 0 cannot happen for a real ray; q = 0 means a degenerate ray
    }
    t0 = q / a;
    t1 = c / q;
    if (t0 > t1) {
        std::swap(t0, t1);
    }
    return true;
}

bool Sphere::intersect(const Ray& ray, double t_max, Hit& hit) const {
    double t0 = 0;
    double t1 = 0;
    if (!solve(ray, t0, t1)) {
        return false;
    }
    double t = t0;
    if (!(t > 0)) {
        t = t1;  // the origin is inside the sphere (or the near root is behind it)
    }
    if (!(t > 0) || t >= t_max) {
        return false;
    }
    // Project the point back onto the sphere: its error is then a few ulps of |C| + R whatever t was.
    const Vec3 from_center = ray.at(t) - center_;
    const Vec3 normal = from_center / length(from_center);
    hit.t = t;
    hit.point = center_ + normal * radius_;
    hit.normal = normal;
    hit.shading_normal = normal;
    const double phi = std::atan2(normal.z, normal.x);
    hit.uv = {(phi < 0 ? phi + 2 * kPi : phi) / (2 * kPi), std::acos(std::clamp(normal.y, -1.0, 1.0)) / kPi};
    hit.error = kHitRelativeError * (max_component(abs(center_)) + radius_);
    return true;
}

bool Sphere::occluded(const Ray& ray, double t_max) const {
    double t0 = 0;
    double t1 = 0;
    if (!solve(ray, t0, t1)) {
        return false;
    }
    return (t0 > 0 && t0 < t_max) || (t1 > 0 && t1 < t_max);
}

std::optional<ShapeSample> Sphere::sample_area(Point2 u) const {
    // Uniform on the sphere: z uniform in [−1, 1] (Archimedes' hat-box theorem), φ uniform.
    const double z = 1 - 2 * u.x;
    const double r = safe_sqrt(1 - z * z);
    const double phi = 2 * kPi * u.y;
    const Vec3 n{r * std::cos(phi), r * std::sin(phi), z};
    return ShapeSample{center_ + radius_ * n, n, 1 / area()};
}

std::unique_ptr<Shape> Sphere::create(Params& params, const BuildContext&) {
    const Vec3 center = params.vec3("center", {0, 0, 0});
    const double radius = params.positive("radius");
    return std::make_unique<Sphere>(center, radius);
}

}  // namespace glint
