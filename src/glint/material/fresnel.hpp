// Fresnel reflectance and Snell refraction (paper §VIII, as corrected by the errata).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "glint/core/color.hpp"
#include "glint/core/vec.hpp"

namespace glint {

// Exact Fresnel reflectance of unpolarised light at a smooth dielectric interface: the mean of the s-
// and p-polarised reflectances. `cos_i` is the cosine between the incident direction and the normal on
// the side of index n1 (the light arrives from n1 into n2). A negative cos_i means the light arrives
// from the other side: the indices are swapped. Returns 1 under total internal reflection.
inline double fresnel_dielectric(double cos_i, double n1, double n2) {
    if (cos_i < 0) {
        std::swap(n1, n2);
        cos_i = -cos_i;
    }
    cos_i = std::min(cos_i, 1.0);
    const double eta = n1 / n2;
    const double sin2_t = eta * eta * (1 - cos_i * cos_i);  // Snell: n1 sin θi = n2 sin θt
    if (sin2_t >= 1) {
        return 1;  // total internal reflection
    }
    const double cos_t = std::sqrt(1 - sin2_t);
    const double r_s = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    const double r_p = (n2 * cos_i - n1 * cos_t) / (n2 * cos_i + n1 * cos_t);
    return 0.5 * (r_s * r_s + r_p * r_p);
}

// Reflectance at normal incidence, R₀ = ((n1 − n2) / (n1 + n2))².
inline double fresnel_r0(double n1, double n2) {
    return sqr((n1 - n2) / (n1 + n2));
}

// Schlick's approximation R₀ + (1 − R₀)(1 − cos θ)⁵, per channel for coloured (metallic) R₀.
inline double schlick(double cos_theta, double r0) {
    const double m = std::clamp(1 - cos_theta, 0.0, 1.0);
    return r0 + (1 - r0) * (m * m) * (m * m) * m;
}
inline Rgb schlick(double cos_theta, const Rgb& r0) {
    return {schlick(cos_theta, r0.r), schlick(cos_theta, r0.g), schlick(cos_theta, r0.b)};
}
// Schlick's form rising to R₉₀ instead of 1 at grazing incidence: R₀ + (R₉₀ − R₀)(1 − cos θ)⁵ (glTF's
// fresnel with f90). A lobe of weight w with Schlick's Fresnel of F₀ is schlick(cos θ, w F₀, w).
inline Rgb schlick(double cos_theta, const Rgb& r0, double r90) {
    const double grazing = schlick(cos_theta, 0.0);  // (1 − cos θ)⁵
    return r0 + (Rgb(r90) - r0) * grazing;
}

// Refraction per the errata to eq. 19–21. `incident` is the unit direction of travel (towards the
// surface), `normal` a unit normal of the interface, n1 the index on the normal's side and n2 the
// other. If the ray leaves through the normal's side (I·N > 0), N is flipped and n1, n2 swapped. Then
// η = n1/n2, c₁ = −N·I, k = 1 − η²(1 − c₁²); nullopt under total internal reflection (k < 0), otherwise
// the unit transmitted direction T = ηI + (ηc₁ − √k)N.
inline std::optional<Vec3> refract(const Vec3& incident, Vec3 normal, double n1, double n2) {
    if (dot(incident, normal) > 0) {
        normal = -normal;
        std::swap(n1, n2);
    }
    const double eta = n1 / n2;
    const double c1 = -dot(normal, incident);
    const double k = 1 - eta * eta * (1 - c1 * c1);
    if (k < 0) {
        return std::nullopt;
    }
    return eta * incident + (eta * c1 - std::sqrt(k)) * normal;
}

}  // namespace glint
