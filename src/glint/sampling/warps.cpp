#include "glint/sampling/warps.hpp"

#include "glint/core/math.hpp"

namespace glint {

namespace {
// The unit vector at polar angle θ (given by its cosine and sine) and azimuth 2π·v about +z.
Vec3 direction_from(double cos_theta, double sin_theta, double v) {
    const SinCos azimuth = sincos_turns(v);
    return {sin_theta * azimuth.cos, sin_theta * azimuth.sin, cos_theta};
}
Vec3 direction_from(double cos_theta, double v) {
    return direction_from(cos_theta, safe_sqrt(1 - cos_theta * cos_theta), v);
}
}  // namespace

// The thin lens repeats it in AVX2 lanes, operation for operation (camera/thin_lens.cpp,
// disk_concentric_lanes): change both together.
Point2 square_to_disk_concentric(Point2 u) {
    const double a = 2 * u.x - 1;
    const double b = 2 * u.y - 1;
    if (a == 0 && b == 0) {
        return {0, 0};
    }
    // The square's concentric squares (|a| or |b| constant) become circles of radius r; the position
    // along each square's edge becomes the angle, linearly, which is what keeps areas equal.
    // The angle within the octant, |ψ| ≤ π/4, needs no reduction before its series; the second case is
    // φ = π/2 − ψ, whose cosine and sine are sin ψ and cos ψ.
    if (std::abs(a) > std::abs(b)) {
        const SinCos psi = sincos_quarter_pi((kPi / 4) * (b / a));
        return {a * psi.cos, a * psi.sin};
    }
    const SinCos psi = sincos_quarter_pi((kPi / 4) * (a / b));
    return {b * psi.sin, b * psi.cos};
}

double uniform_disk_pdf() {
    return kInvPi;
}

Vec3 square_to_uniform_hemisphere(Point2 u) {
    // Archimedes: z is uniform on a sphere, so uniform in [0, 1] on the upper half. 1 − u.x keeps z > 0.
    return direction_from(1 - u.x, u.y);
}

double uniform_hemisphere_pdf() {
    return 0.5 * kInvPi;
}

Vec3 square_to_cosine_power_hemisphere(Point2 u, double exponent) {
    // The marginal density of z = cos θ is (e+1) z^e on [0, 1]; its CDF is z^(e+1), inverted here.
    // 1 − u.x ∈ (0, 1] so that z is never 0 (a grazing direction with zero density).
    const double cos_theta = std::pow(1 - u.x, 1 / (exponent + 1));
    return direction_from(cos_theta, u.y);
}

double cosine_power_hemisphere_pdf(const Vec3& local, double exponent) {
    if (local.z < 0) {
        return 0;
    }
    return (exponent + 1) * (0.5 * kInvPi) * std::pow(local.z, exponent);
}

Vec3 square_to_uniform_sphere(Point2 u) {
    return direction_from(1 - 2 * u.x, u.y);
}

double uniform_sphere_pdf() {
    return 0.25 * kInvPi;
}

Vec3 square_to_uniform_cone(Point2 u, double cos_max) {
    // z is uniform in (cos_max, 1] (the cone's cap is a zone of the sphere): 1 − z = u.x (1 − cos_max),
    // never reaching the rim, so a sample never lies exactly on a light's silhouette. sin θ comes from
    // 1 − z² = (1 − z)(1 + z), which keeps its precision in the narrow cones of small, far lights.
    const double one_minus_z = u.x * (1 - cos_max);
    return direction_from(1 - one_minus_z, safe_sqrt(one_minus_z * (2 - one_minus_z)), u.y);
}

double uniform_cone_pdf(double cos_max) {
    return 1 / (2 * kPi * (1 - cos_max));
}

}  // namespace glint
