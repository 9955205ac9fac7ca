// Cylinder {type: cylinder, base: [x, y, z], top: [x, y, z], radius: r, capped: true}
// base and top are the centres of the two ends (they must differ); `capped` (default true) closes the
// ends with disks, making the cylinder a closed shape; capped: false leaves an open tube whose normal
// points away from the axis on both sides of the wall (shading turns it towards the viewer).
// uv: on the side (angle / 2π, height fraction); on the caps (angle / 2π, distance from axis / r).
#include "glint/geometry/cylinder.hpp"

#include "glint/geometry/planar.hpp"
#include "glint/params/params.hpp"

namespace glint {

Cylinder::Cylinder(const Vec3& base, const Vec3& top, double radius, bool capped)
    : axis_(base, top), radius_(radius), capped_(capped) {}

Bounds3 Cylinder::bounds() const {
    Bounds3 b = disk_bounds(axis_.base, axis_.frame.n, radius_);
    b.grow(disk_bounds(axis_.point_to_world({0, 0, axis_.height}), axis_.frame.n, radius_));
    return b;
}

double Cylinder::solve(const Ray& local, double t_max, Part& part) const {
    double best = kInf;
    const Vec3& o = local.origin;
    const Vec3& d = local.direction;
    // Side: x² + y² = r², the sphere's robust quadratic (errata §5.1) in the xy plane.
    const double a = d.x * d.x + d.y * d.y;
    if (a > 0) {
        const double h = o.x * d.x + o.y * d.y;
        const double c = o.x * o.x + o.y * o.y - radius_ * radius_;
        // The discriminant h² − a c as a (r² − |l|²), l the closest point of the line to the axis.
        const double lx = o.x - (h / a) * d.x;
        const double ly = o.y - (h / a) * d.y;
        const double discriminant = a * (radius_ * radius_ - (lx * lx + ly * ly));
        if (discriminant >= 0) {
            const double q = -(h + std::copysign(std::sqrt(discriminant), h));
            if (q != 0) {
                for (const double t : {q / a, c / q}) {
                    const double z = o.z + t * d.z;
                    if (t > 0 && t < t_max && t < best && z >= 0 && z <= axis_.height) {
                        best = t;
                        part = Part::Side;
                    }
                }
            }
        }
    }
    if (capped_) {
        const double t_base = cap_hit_t(local, 0, radius_, std::min(best, t_max));
        if (t_base != kInf) {
            best = t_base;
            part = Part::Base;
        }
        const double t_top = cap_hit_t(local, axis_.height, radius_, std::min(best, t_max));
        if (t_top != kInf) {
            best = t_top;
            part = Part::Top;
        }
    }
    return best;
}

bool Cylinder::intersect(const Ray& ray, double t_max, Hit& hit) const {
    const Ray local = axis_.to_local(ray);
    Part part = Part::Side;
    const double t = solve(local, t_max, part);
    if (t == kInf) {
        return false;
    }
    Vec3 p = local.at(t);
    Vec3 n;
    const double rho = std::hypot(p.x, p.y);
    if (part == Part::Side) {
        // Back onto the wall: the exact radius, the height within the ends.
        p.x *= radius_ / rho;
        p.y *= radius_ / rho;
        p.z = std::clamp(p.z, 0.0, axis_.height);
        n = {p.x / radius_, p.y / radius_, 0};
        hit.uv = {angle_fraction(p.x, p.y), p.z / axis_.height};
    } else {
        p.z = part == Part::Base ? 0 : axis_.height;
        n = {0, 0, part == Part::Base ? -1.0 : 1.0};
        hit.uv = {angle_fraction(p.x, p.y), std::min(rho / radius_, 1.0)};
    }
    hit.t = t;
    hit.point = axis_.point_to_world(p);
    hit.normal = axis_.vector_to_world(n);
    hit.shading_normal = hit.normal;
    hit.error = kHitRelativeError * (max_component(abs(hit.point)) + max_component(abs(axis_.base)) +
                                     std::max(radius_, axis_.height));
    return true;
}

bool Cylinder::occluded(const Ray& ray, double t_max) const {
    Part part = Part::Side;
    return solve(axis_.to_local(ray), t_max, part) != kInf;
}

double Cylinder::area() const {
    return 2 * kPi * radius_ * axis_.height + (capped_ ? 2 * kPi * radius_ * radius_ : 0);
}

std::optional<ShapeSample> Cylinder::sample_area(Point2 u) const {
    // The side with probability side area / area (then u.x rescaled to [0, 1)), else a cap, each by area.
    const double side = 2 * kPi * radius_ * axis_.height;
    const double side_fraction = side / area();
    const double phi = 2 * kPi * u.y;
    Vec3 p, n;
    if (u.x < side_fraction) {
        n = {std::cos(phi), std::sin(phi), 0};
        p = {radius_ * n.x, radius_ * n.y, axis_.height * (u.x / side_fraction)};
    } else {
        // The caps share the rest equally: which cap from the first half, the radius from the rest.
        const double x = (u.x - side_fraction) / (1 - side_fraction);
        const bool top = x >= 0.5;
        const double r = radius_ * std::sqrt(std::clamp(top ? 2 * x - 1 : 2 * x, 0.0, 1.0));
        p = {r * std::cos(phi), r * std::sin(phi), top ? axis_.height : 0};
        n = {0, 0, top ? 1.0 : -1.0};
    }
    return ShapeSample{axis_.point_to_world(p), axis_.vector_to_world(n), 1 / area()};
}

std::unique_ptr<Shape> Cylinder::create(Params& params, const BuildContext&) {
    const Vec3 base = params.vec3("base", {0, 0, 0});
    const Vec3 top = params.vec3("top", {0, 1, 0});
    const double radius = params.positive("radius");
    const bool capped = params.boolean("capped", true);
    if (!(length(top - base) > 0)) {
        params.fail("top", "cylinder top must differ from base: they are the centres of its two ends");
    }
    return std::make_unique<Cylinder>(base, top, radius, capped);
}

}  // namespace glint
