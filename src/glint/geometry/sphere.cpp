// Sphere {type: sphere, center: [x, y, z], radius: r}.
#include "glint/geometry/sphere.hpp"

#include "glint/params/params.hpp"

namespace glint {

Bounds3 Sphere::bounds() const {
    const Vec3 r{radius_, radius_, radius_};
    return {center_ - r, center_ + r};
}

bool Sphere::intersect(const Ray& ray, double t_max, Hit& hit) const {
    double t = 0;
    if (!sphere_hit_t(center_, radius_, ray, t_max, t)) {
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
    return sphere_occludes(center_, radius_, ray, t_max);
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
