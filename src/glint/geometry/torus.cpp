// Torus {type: torus, center: [x, y, z], axis: [x, y, z], major_radius: R, minor_radius: r}
// The tube of radius r around the circle of radius R about `axis` (default [0, 1, 0]: lying flat);
// 0 < r < R (r ≥ R would make a horn or spindle torus that passes through its own centre).
// uv: u = angle around the axis / 2π, v = angle around the tube / 2π (0 on the outer equator).
#include "glint/geometry/torus.hpp"

#include "glint/core/polynomial.hpp"
#include "glint/geometry/planar.hpp"
#include "glint/params/params.hpp"

namespace glint {

Torus::Torus(const Vec3& center, const Vec3& axis, double major, double minor)
    : center_(center),
      frame_(Frame::from_normal(normalize(axis))),
      major_(major),
      minor_(minor),
      scale_(major + minor),
      unit_major_(major / (major + minor)),
      unit_minor_(minor / (major + minor)) {}

Bounds3 Torus::bounds() const {
    // The ring of radius R swept by a ball of radius r.
    Bounds3 b = disk_bounds(center_, frame_.n, major_);
    const Vec3 r{minor_, minor_, minor_};
    return {b.lo - r, b.hi + r};
}

double Torus::solve(const Ray& ray, double t_max, Vec3& unit_point) const {
    const Vec3 o = frame_.to_local(ray.origin - center_) / scale_;
    const Vec3 d = frame_.to_local(ray.direction) / scale_;
    const double d_length = length(d);
    if (!(d_length > 0)) {
        return kInf;
    }
    const Vec3 du = d / d_length;
    // Move the origin to the line's closest point to the centre: the coefficients then stay of order
    // one and the roots lie in [−half, half], half the chord through the unit bounding sphere.
    const double shift = -dot(o, du);
    const Vec3 oc = o + shift * du;
    const double oc2 = dot(oc, oc);
    if (oc2 > 1) {
        return kInf;
    }
    const double half = std::sqrt(1 - oc2) * (1 + 1e-9) + 1e-12;  // a margin so no root is cut off
    // The ray's t ∈ (0, t_max) is s ∈ (−shift, t_max·|d| − shift) along du from oc.
    const double lo = std::max(-half, -shift);
    const double hi = std::min(half, t_max * d_length - shift);
    if (!(lo < hi)) {
        return kInf;
    }
    // The torus lies within the slab |z| ≤ r: most rays that miss it are cut off here, cheaply.
    if (du.z != 0) {
        const double s0 = (-unit_minor_ - oc.z) / du.z, s1 = (unit_minor_ - oc.z) / du.z;
        if (std::max(s0, s1) < lo || std::min(s0, s1) > hi) {
            return kInf;
        }
    } else if (std::abs(oc.z) > unit_minor_) {
        return kInf;
    }
    // (|p|² + R² − r²)² − 4 R² (x² + y²) = 0 for p = oc + s du, as a quartic in s.
    const double R2 = unit_major_ * unit_major_;
    const double dd = dot(du, du);
    const double e = dot(oc, du);
    const double g = oc2 + R2 - unit_minor_ * unit_minor_;
    const double a2 = du.x * du.x + du.y * du.y;
    const double b2 = oc.x * du.x + oc.y * du.y;
    const double c2 = oc.x * oc.x + oc.y * oc.y;
    const double coefficients[5] = {g * g - 4 * R2 * c2, 4 * e * g - 8 * R2 * b2,
                                    4 * e * e + 2 * dd * g - 4 * R2 * a2, 4 * dd * e, dd * dd};
    double roots[4];
    const int count = polynomial_roots(coefficients, 4, lo, hi, roots);
    for (int i = 0; i < count; ++i) {
        const double t = (shift + roots[i]) / d_length;
        if (t > 0 && t < t_max) {
            unit_point = oc + roots[i] * du;
            return t;
        }
    }
    return kInf;
}

bool Torus::intersect(const Ray& ray, double t_max, Hit& hit) const {
    Vec3 p;
    const double t = solve(ray, t_max, p);
    if (t == kInf) {
        return false;
    }
    // Project onto the torus: the nearest point of the core circle, then out along the tube's radius.
    // rho > 0: the tube does not reach the axis when r < R (the guard is against a NaN, not a case).
    const double rho = std::hypot(p.x, p.y);
    const Vec3 radial = rho > 0 ? Vec3{p.x / rho, p.y / rho, 0} : Vec3{1, 0, 0};
    const Vec3 ring = unit_major_ * radial;
    const Vec3 n = normalize(p - ring);
    const Vec3 on_surface = ring + unit_minor_ * n;
    hit.t = t;
    hit.point = center_ + frame_.to_world(on_surface * scale_);
    hit.normal = frame_.to_world(n);
    hit.shading_normal = hit.normal;
    const double tube_angle = std::atan2(n.z, dot(n, radial));
    hit.uv = {std::atan2(-p.y, -p.x) / (2 * kPi) + 0.5,
              (tube_angle < 0 ? tube_angle + 2 * kPi : tube_angle) / (2 * kPi)};
    hit.error = kHitRelativeError * (max_component(abs(hit.point)) + max_component(abs(center_)) + scale_);
    return true;
}

bool Torus::occluded(const Ray& ray, double t_max) const {
    Vec3 unused;
    return solve(ray, t_max, unused) != kInf;
}

std::optional<ShapeSample> Torus::sample_area(Point2 u) const {
    // The area element is r (R + r cos θ) dθ dφ: φ is uniform, θ has the distribution function
    // (θ + (r/R) sin θ) / 2π, increasing since r < R, inverted by Newton's method within a bracket.
    const double ratio = minor_ / major_;
    const double target = 2 * kPi * u.x;
    double lo = 0, hi = 2 * kPi, theta = target;
    for (int i = 0; i < 100; ++i) {
        const double f = theta + ratio * std::sin(theta) - target;
        if (f < 0) {
            lo = theta;
        } else {
            hi = theta;
        }
        double next = theta - f / (1 + ratio * std::cos(theta));
        if (!(next > lo && next < hi)) {
            next = 0.5 * (lo + hi);
        }
        if (std::abs(next - theta) < 1e-15) {
            theta = next;
            break;
        }
        theta = next;
    }
    const double phi = 2 * kPi * u.y;
    const Vec3 n{std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), std::sin(theta)};
    const Vec3 ring{major_ * std::cos(phi), major_ * std::sin(phi), 0};
    return ShapeSample{center_ + frame_.to_world(ring + minor_ * n), frame_.to_world(n), 1 / area()};
}

std::unique_ptr<Shape> Torus::create(Params& params, const BuildContext&) {
    const Vec3 center = params.vec3("center", {0, 0, 0});
    const Vec3 axis = params.direction("axis", {0, 1, 0});
    const double major = params.positive("major_radius");
    const double minor = params.positive("minor_radius");
    if (!(minor < major)) {
        params.fail("minor_radius", "torus minor_radius must be less than major_radius (a ring torus)");
    }
    return std::make_unique<Torus>(center, axis, major, minor);
}

}  // namespace glint
