// Disk {type: disk, center: [x, y, z], normal: [x, y, z], radius: r}
// Annulus {type: annulus, center, normal, inner_radius: r0, outer_radius: r1} with 0 <= r0 < r1.
// `normal` defaults to [0, 1, 0] (facing up) and is normalised; Hit::normal is always that side.
// uv: u = angle / 2π around the normal (from the frame's tangent), v = distance from the centre / radius.
#include "glint/geometry/disk.hpp"

#include "glint/geometry/planar.hpp"
#include "glint/params/params.hpp"

namespace glint {

Disk::Disk(const Vec3& center, const Vec3& normal, double radius, double inner_radius)
    : center_(center),
      frame_(Frame::from_normal(normalize(normal))),
      radius_(radius),
      inner_radius_(inner_radius) {}

Bounds3 Disk::bounds() const {
    return disk_bounds(center_, frame_.n, radius_);
}

double Disk::solve(const Ray& ray, double t_max, Vec3& point) const {
    const double t = plane_hit_t(ray, center_, frame_.n);
    if (!(t > 0) || t >= t_max) {
        return kInf;
    }
    point = point_on_plane(ray, t, center_, frame_.n);
    const double r2 = length_squared(point - center_);
    if (r2 > radius_ * radius_ || r2 < inner_radius_ * inner_radius_) {
        return kInf;
    }
    return t;
}

bool Disk::intersect(const Ray& ray, double t_max, Hit& hit) const {
    Vec3 p;
    const double t = solve(ray, t_max, p);
    if (t == kInf) {
        return false;
    }
    const Vec3 local = frame_.to_local(p - center_);
    const double phi = std::atan2(local.y, local.x);
    hit.t = t;
    hit.point = p;
    hit.normal = frame_.n;
    hit.shading_normal = frame_.n;
    hit.uv = {(phi < 0 ? phi + 2 * kPi : phi) / (2 * kPi), std::hypot(local.x, local.y) / radius_};
    hit.error = kHitRelativeError * (max_component(abs(p)) + max_component(abs(center_)) + radius_);
    return true;
}

bool Disk::occluded(const Ray& ray, double t_max) const {
    Vec3 unused;
    return solve(ray, t_max, unused) != kInf;
}

std::optional<ShapeSample> Disk::sample_area(Point2 u) const {
    // Uniform by area: the radius squared is uniform between inner² and outer², the angle uniform.
    const double r = std::sqrt(lerp(u.x, inner_radius_ * inner_radius_, radius_ * radius_));
    const SinCos phi = sincos_turns(u.y);
    const Vec3 p = center_ + frame_.to_world({r * phi.cos, r * phi.sin, 0});
    return ShapeSample{p, frame_.n, 1 / area()};
}

std::unique_ptr<Shape> Disk::create(Params& params, const BuildContext&) {
    const Vec3 center = params.vec3("center", {0, 0, 0});
    const Vec3 normal = params.direction("normal", {0, 1, 0});
    const double radius = params.positive("radius");
    return std::make_unique<Disk>(center, normal, radius);
}

std::unique_ptr<Shape> Disk::create_annulus(Params& params, const BuildContext&) {
    const Vec3 center = params.vec3("center", {0, 0, 0});
    const Vec3 normal = params.direction("normal", {0, 1, 0});
    const double inner = params.non_negative("inner_radius", 0);
    const double outer = params.positive("outer_radius");
    if (!(inner < outer)) {
        params.fail("inner_radius", "annulus inner_radius must be less than outer_radius");
    }
    return std::make_unique<Disk>(center, normal, outer, inner);
}

}  // namespace glint
