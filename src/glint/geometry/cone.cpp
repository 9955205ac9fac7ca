// Cone {type: cone, base: [x, y, z], apex: [x, y, z], radius: r, capped: true}
// `base` is the centre of the base disk, `apex` the tip (they must differ); `capped` (default true)
// closes the base with a disk. Open cones keep the outward side normal on both sides of the wall.
// uv: on the side (angle / 2π, height fraction from base to apex); on the cap (angle / 2π, ρ / r).
#include "glint/geometry/cone.hpp"

#include "glint/geometry/planar.hpp"
#include "glint/params/params.hpp"

namespace glint {

Cone::Cone(const Vec3& base, const Vec3& apex, double radius, bool capped)
    : axis_(base, apex), radius_(radius), slant_(std::hypot(radius, axis_.height)), capped_(capped) {}

Bounds3 Cone::bounds() const {
    Bounds3 b = disk_bounds(axis_.base, axis_.frame.n, radius_);
    b.grow(axis_.point_to_world({0, 0, axis_.height}));
    return b;
}

double Cone::solve(const Ray& local, double t_max, bool& on_cap) const {
    double best = kInf;
    const Vec3& o = local.origin;
    const Vec3& d = local.direction;
    const double h = axis_.height;
    // Side: f = x² + y² − k² (h − z)² = 0 with k = r / h, for 0 ≤ z ≤ h (the other nappe is cut off).
    // As a t² + 2 b t + c with w0 = h − o.z the distance below the apex.
    const double k2 = (radius_ / h) * (radius_ / h);
    const double w0 = h - o.z;
    const double a = d.x * d.x + d.y * d.y - k2 * d.z * d.z;
    const double b = o.x * d.x + o.y * d.y + k2 * w0 * d.z;
    const double c = o.x * o.x + o.y * o.y - k2 * w0 * w0;
    const double discriminant = b * b - a * c;
    if (discriminant >= 0) {
        // q never cancels; the roots are q / a (absent when the ray is parallel to the slant, a = 0)
        // and c / q.
        const double q = -(b + std::copysign(std::sqrt(discriminant), b));
        for (double t : {a != 0 ? q / a : kInf, q != 0 ? c / q : kInf}) {
            if (!std::isfinite(t)) {
                continue;
            }
            // One Newton step on f evaluated at the point: the discriminant may have lost digits.
            const Vec3 p = local.at(t);
            const double f = p.x * p.x + p.y * p.y - k2 * sqr(h - p.z);
            const double df = 2 * (a * t + b);
            if (df != 0 && std::isfinite(f / df)) {
                t -= f / df;
            }
            const double z = o.z + t * d.z;
            if (t > 0 && t < t_max && t < best && z >= 0 && z <= h) {
                best = t;
                on_cap = false;
            }
        }
    }
    if (capped_) {
        const double t_cap = cap_hit_t(local, 0, radius_, std::min(best, t_max));
        if (t_cap != kInf) {
            best = t_cap;
            on_cap = true;
        }
    }
    return best;
}

bool Cone::intersect(const Ray& ray, double t_max, Hit& hit) const {
    const Ray local = axis_.to_local(ray);
    bool on_cap = false;
    const double t = solve(local, t_max, on_cap);
    if (t == kInf) {
        return false;
    }
    Vec3 p = local.at(t);
    Vec3 n;
    const double rho = std::hypot(p.x, p.y);
    const double h = axis_.height;
    if (!on_cap) {
        // Project (ρ, z) onto the side's line from the rim (r, 0) to the apex (0, h); the normal of
        // that line is (h, r) / slant in the (ρ, z) half-plane.
        const double along = std::clamp(((rho - radius_) * -radius_ + p.z * h) / slant_, 0.0, slant_);
        const double new_rho = radius_ - along * radius_ / slant_;
        const double cos_phi = rho > 0 ? p.x / rho : 1;
        const double sin_phi = rho > 0 ? p.y / rho : 0;
        p = {new_rho * cos_phi, new_rho * sin_phi, along * h / slant_};
        n = {h / slant_ * cos_phi, h / slant_ * sin_phi, radius_ / slant_};
        hit.uv = {angle_fraction(cos_phi, sin_phi), p.z / h};
    } else {
        p.z = 0;
        n = {0, 0, -1};
        hit.uv = {angle_fraction(p.x, p.y), std::min(rho / radius_, 1.0)};
    }
    hit.t = t;
    hit.point = axis_.point_to_world(p);
    hit.normal = axis_.vector_to_world(n);
    hit.shading_normal = hit.normal;
    hit.error = kHitRelativeError *
                (max_component(abs(hit.point)) + max_component(abs(axis_.base)) + std::max(radius_, h));
    return true;
}

bool Cone::occluded(const Ray& ray, double t_max) const {
    bool on_cap = false;
    return solve(axis_.to_local(ray), t_max, on_cap) != kInf;
}

double Cone::area() const {
    return side_area() + (capped_ ? kPi * radius_ * radius_ : 0);
}

std::optional<ShapeSample> Cone::sample_area(Point2 u) const {
    // The side with probability side area / area (u.x rescaled to [0, 1)), else the cap. On the side
    // the area within distance s·slant of the apex grows as s², so s = √(uniform).
    const double side_fraction = side_area() / area();
    const double phi = 2 * kPi * u.y;
    const double c = std::cos(phi), s = std::sin(phi);
    Vec3 p, n;
    if (u.x < side_fraction) {
        const double from_apex = std::sqrt(u.x / side_fraction);
        p = {radius_ * from_apex * c, radius_ * from_apex * s, axis_.height * (1 - from_apex)};
        n = {axis_.height / slant_ * c, axis_.height / slant_ * s, radius_ / slant_};
    } else {
        const double r =
            radius_ * std::sqrt(std::clamp((u.x - side_fraction) / (1 - side_fraction), 0.0, 1.0));
        p = {r * c, r * s, 0};
        n = {0, 0, -1};
    }
    return ShapeSample{axis_.point_to_world(p), axis_.vector_to_world(n), 1 / area()};
}

std::unique_ptr<Shape> Cone::create(Params& params, const BuildContext&) {
    const Vec3 base = params.vec3("base", {0, 0, 0});
    const Vec3 apex = params.vec3("apex", {0, 1, 0});
    const double radius = params.positive("radius");
    const bool capped = params.boolean("capped", true);
    if (!(length(apex - base) > 0)) {
        params.fail("apex", "cone apex must differ from base (the centre of its base disk)");
    }
    return std::make_unique<Cone>(base, apex, radius, capped);
}

}  // namespace glint
