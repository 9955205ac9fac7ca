// Sphere {type: sphere, center: [x, y, z], radius: r}.
#include "glint/geometry/sphere.hpp"

#include "glint/core/frame.hpp"
#include "glint/params/params.hpp"
#include "glint/sampling/warps.hpp"

#ifdef __SSE2__
#include <emmintrin.h>
#endif

namespace glint {

namespace {
// to = v, x and y in one 16-byte store (see fill_hit).
inline void store_vec3(Vec3& to, const Vec3& v) {
#ifdef __SSE2__
    _mm_storeu_pd(&to.x, _mm_set_pd(v.y, v.x));
    to.z = v.z;
#else
    to = v;
#endif
}
}  // namespace

Bounds3 Sphere::bounds() const {
    const Vec3 r{radius_, radius_, radius_};
    return {center_ - r, center_ + r};
}

bool Sphere::intersect(const Ray& ray, double t_max, Hit& hit) const {
    double t = 0;
    if (!sphere_hit_t(center_, radius_, ray, inverse_length_squared(ray.direction), t_max, t)) {
        return false;
    }
    fill_hit(ray, t, hit);
    return true;
}

void Sphere::fill_hit(const Ray& ray, double t, Hit& hit) const {
    // Project the point back onto the sphere: its error is then a few ulps of |C| + R whatever t was.
    const Vec3 from_center = ray.at(t) - center_;
    // from_center / R is a unit vector to within t's rounding: normalized without a division.
    const Vec3 normal = normalize_near_unit(from_center * inverse_radius_);
    // Each vector stored as an x, y pair and a z: written as whole Vec3s, GCC packed x and y through a
    // slot on the stack for 16-byte stores, and the 16-byte load of that slot waited for the two 8-byte
    // stores before it (a failed store-to-load forward, 38 % of fill_hit's time in perf); stored one
    // double at a time, the readers' 16-byte loads of the Hit would wait the same way.
    hit.t = t;
    store_vec3(hit.point, center_ + normal * radius_);
    store_vec3(hit.normal, normal);
    store_vec3(hit.shading_normal, normal);
    hit.uv = kUvFromSphereNormal;  // surface_uv computes sphere_uv(normal) if a texture asks
    hit.error = kHitRelativeError * (max_component(abs(center_)) + radius_);
}

bool Sphere::occluded(const Ray& ray, double t_max) const {
    return sphere_occludes(center_, radius_, ray, inverse_length_squared(ray.direction), t_max);
}

std::optional<ShapeSample> Sphere::sample_area(Point2 u) const {
    const Vec3 n = square_to_uniform_sphere(u);
    return ShapeSample{center_ + radius_ * n, n, 1 / area()};
}

bool Sphere::seen_from_outside(const Vec3& ref) const {
    // A margin of relative 1e-9 keeps points on the surface (rounding either way) on area sampling.
    return length_squared(ref - center_) > sqr(radius_) * (1 + 1e-9);
}

namespace {
// 1 − cos θ_max of the cone a sphere subtends, from sin² θ_max = R²/d², without cancellation:
// 1 − cos = sin² / (1 + cos). (pbrt-v4 switches to a Taylor series for small cones instead.)
double one_minus_cos_max(double sin2_max) {
    return sin2_max / (1 + safe_sqrt(1 - sin2_max));
}

// The cone's density per steradian at distance² d2 from the centre of a sphere of radius R (1/R given):
// 1 / (2π (1 − cos θ_max)) = (1 + cos θ_max) / (2π sin² θ_max), with sin² θ_max = R² / d² and
// cos θ_max = √(d² − R²) / d, is (d² + d √(d² − R²)) / (2π R²). Two square roots side by side and no
// division, where 1 / (2π one_minus_cos_max(R² / d²)) took a division, a square root and two more
// divisions one after another, and every light sample of a sphere with a learnt cap waited for them
// (LightVisibility's mixture density). A cone sample and pdf_seen_from both return it, to the bit.
double cone_density(double d2, double radius, double inverse_radius) {
    return (d2 + std::sqrt(d2) * safe_sqrt(d2 - sqr(radius))) * (sqr(inverse_radius) * (0.5 * kInvPi));
}
}  // namespace

std::optional<SeenSample> Sphere::sample_seen_from(const Vec3& ref, Point2 u) const {
    if (!seen_from_outside(ref)) {
        return Shape::sample_seen_from(ref, u);
    }
    // A uniform direction in the cone towards the centre, then the point of the sphere it meets first,
    // found by the angle α at the centre (computed directly, not by intersecting a ray).
    const Vec3 to_center = center_ - ref;
    const double d2 = length_squared(to_center);
    const double sin2_max = sqr(radius_) / d2;
    const double sin_max = std::sqrt(sin2_max);
    const double omc_max = one_minus_cos_max(sin2_max);
    const double omc = u.x * omc_max;  // 1 − cos θ, uniform in [0, 1 − cos θ_max]
    const double cos_theta = 1 - omc;
    const double sin2_theta = omc * (2 - omc);
    const double cos_alpha = sin2_theta / sin_max + cos_theta * safe_sqrt(1 - sin2_theta / sin2_max);
    const double sin_alpha = safe_sqrt(1 - cos_alpha * cos_alpha);
    const SinCos phi = sincos_turns(u.y);
    const Frame frame = Frame::from_normal(to_center / std::sqrt(d2));
    const Vec3 normal = frame.to_world({-sin_alpha * phi.cos, -sin_alpha * phi.sin, -cos_alpha});
    const Vec3 point = center_ + radius_ * normal;
    const Vec3 to_point = point - ref;
    const double distance = length(to_point);
    if (!(distance > 0)) {
        return std::nullopt;
    }
    return SeenSample{point, normal, to_point / distance, cone_density(d2, radius_, inverse_radius_)};
}

double Sphere::cone_pdf(const Vec3& ref) const {
    return cone_density(length_squared(center_ - ref), radius_, inverse_radius_);
}

double Sphere::pdf_seen_from(const Vec3& ref, const Vec3& wi, const Hit& on_shape) const {
    return seen_from_outside(ref) ? cone_pdf(ref) : Shape::pdf_seen_from(ref, wi, on_shape);
}

double Sphere::pdf_seen_from(const Vec3& ref, const Vec3& wi, const Vec3& point, const Vec3& normal) const {
    if (seen_from_outside(ref)) {
        return cone_pdf(ref);
    }
    Hit on_shape;  // what Shape::pdf_seen_from reads of it
    on_shape.point = point;
    on_shape.normal = normal;
    on_shape.shading_normal = normal;
    return Shape::pdf_seen_from(ref, wi, on_shape);
}

std::unique_ptr<Shape> Sphere::create(Params& params, const BuildContext&) {
    const Vec3 center = params.vec3("center", {0, 0, 0});
    const double radius = params.positive("radius");
    return std::make_unique<Sphere>(center, radius);
}

}  // namespace glint
