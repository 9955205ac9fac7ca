// The watertight ray–triangle test of Woop, Benthin and Wald (JCGT 2013), in double precision.
//
// The ray is sheared so that it runs along +z through the origin; each edge of a triangle is then a 2-D
// edge function evaluated on the sheared vertices. A vertex shared by two triangles is sheared to the
// same numbers in both, and an edge shared by two triangles yields exactly negated edge functions, so
// a ray through a shared edge or vertex is counted inside at least one of them: no ray slips through a
// closed mesh. Points exactly on an edge count as inside (both signs are accepted).
// This relies on each product being rounded on its own: no fused multiply-add contraction. The build
// says so explicitly (-ffp-contract=off in CMakeLists.txt): code inlined into the AVX2+FMA traversal
// was contracted otherwise.
#pragma once

#include <cstdint>

#include "glint/core/ray.hpp"

namespace glint {

// What the test needs of a ray, computed once per ray and reused for every triangle.
struct WatertightRay {
    Vec3 origin;
    int kx = 0, ky = 1, kz = 2;  // kz: the dominant axis of the direction; (kx, ky, kz) keeps winding
    double shear_x = 0, shear_y = 0, shear_z = 0;
    double origin_x = 0, origin_y = 0, origin_z = 0;  // origin[kx], origin[ky], origin[kz]

    // Without branches: a bounce ray's dominant axis and its sign are as unpredictable as its
    // direction. Chosen by branches (and read back through Vec3's operator[] with a variable index, a
    // chain of comparisons, at every block test), they cost the bunny's rays 7 % of the kernel's time
    // (bench/accel: 0.933 of it without them).
    explicit WatertightRay(const Ray& ray) : origin(ray.origin) {
        const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
        const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
        const Vec3 a = abs(ray.direction);
        // kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2), looked up from the three
        // comparisons (bits 0, 1, 2: x > y, x > z, y > z; false for a NaN, as in the ternaries).
        constexpr int kLargest[8] = {2, 2, 2, 0, 1, 2, 1, 0};
        const int index =
            static_cast<int>(a.x > a.y) | static_cast<int>(a.x > a.z) << 1 | static_cast<int>(a.y > a.z) << 2;
        constexpr int kNext[3] = {1, 2, 0};
        kz = kLargest[index];
        kx = kNext[kz];
        ky = kNext[kx];
        // Along −kz, x and y trade places, to keep the winding (the sign of the determinant means the
        // same side).
        const int swap = (kx ^ ky) & -static_cast<int>(d[kz] < 0);
        kx ^= swap;
        ky ^= swap;
        shear_x = d[kx] / d[kz];
        shear_y = d[ky] / d[kz];
        shear_z = 1.0 / d[kz];
        origin_x = o[kx];
        origin_y = o[ky];
        origin_z = o[kz];
    }
};

// Barycentric coordinates (b0, b1, b2 of v0, v1, v2) and ray parameter of a triangle hit.
struct TriangleHit {
    double t = 0;
    double b0 = 0, b1 = 0, b2 = 0;
};

// Whether the ray meets the triangle (v0, v1, v2) at t in (0, t_max); fills `out` if so. Degenerate
// triangles (zero area, or seen exactly edge-on) are never hit.
inline bool intersect_triangle(const WatertightRay& ray, const Vec3& v0, const Vec3& v1, const Vec3& v2,
                               double t_max, TriangleHit& out) {
    const Vec3 a = v0 - ray.origin;
    const Vec3 b = v1 - ray.origin;
    const Vec3 c = v2 - ray.origin;
    const double ax = a[ray.kx] - ray.shear_x * a[ray.kz];
    const double ay = a[ray.ky] - ray.shear_y * a[ray.kz];
    const double bx = b[ray.kx] - ray.shear_x * b[ray.kz];
    const double by = b[ray.ky] - ray.shear_y * b[ray.kz];
    const double cx = c[ray.kx] - ray.shear_x * c[ray.kz];
    const double cy = c[ray.ky] - ray.shear_y * c[ray.kz];
    // Edge functions: u for edge (v1, v2), v for (v2, v0), w for (v0, v1).
    const double u = cx * by - cy * bx;
    const double v = ax * cy - ay * cx;
    const double w = bx * ay - by * ax;
    if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) {
        return false;
    }
    double det = u + v + w;
    if (det == 0 || !(det == det)) {
        return false;  // degenerate, or seen edge-on; NaN from non-finite input also misses
    }
    const double az = ray.shear_z * a[ray.kz];
    const double bz = ray.shear_z * b[ray.kz];
    const double cz = ray.shear_z * c[ray.kz];
    double t_scaled = u * az + v * bz + w * cz;  // t · det
    if (det < 0) {
        det = -det;
        t_scaled = -t_scaled;
    }
    if (!(t_scaled > 0) || !(t_scaled < t_max * det)) {
        return false;
    }
    const double inv_det = 1.0 / det;
    const double t = t_scaled * inv_det;
    if (!(t > 0) || !(t < t_max)) {
        return false;  // guards the rounding of the division against the bound tested above
    }
    out.t = t;
    // u, v, w carry det's sign; dividing by |det| with the sign restored gives the weights.
    const double s = (u + v + w) < 0 ? -inv_det : inv_det;
    out.b0 = u * s;
    out.b1 = v * s;
    out.b2 = w * s;
    return true;
}

}  // namespace glint
