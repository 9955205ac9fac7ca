// Materials: how a surface scatters light (paper §VI, VIII). Every material provides evaluate, sample
// and pdf of its BSDF, which must agree (the tests check it).
//
// Directions are world-space unit vectors pointing away from the surface: `wo` towards the viewer,
// `wi` towards the light. f(wo, wi) excludes the cosine factor. Either may lie on either side of the
// surface (hit.normal points out of closed shapes; a ray inside glass sees wo below it).
//
// A sample's path weight is f · |cos θi| / pdf with cos θi = dot(hit.shading_normal, wi) (absolute:
// transmitted directions lie on the other side). For delta lobes (mirror, smooth glass, the coat of
// plastic) f and pdf are Dirac weights: f holds the 1/|cos θi| that the weight cancels and pdf the
// discrete probability of choosing that lobe; evaluate() and pdf() return 0 for them, since no other
// sampling strategy can find a delta direction.
#pragma once

#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/color.hpp"
#include "glint/geometry/hit.hpp"
#include "glint/params/name_table.hpp"

namespace glint {

class Params;
struct BuildContext;

struct BsdfSample {
    Vec3 wi;
    Rgb f;               // BSDF value for (wo, wi)
    double pdf = 0;      // solid-angle density of wi; for a delta lobe, the discrete probability
    bool delta = false;  // a mirror or refraction direction: f and pdf are Dirac weights
};

class Material {
  public:
    virtual ~Material() = default;

    virtual Rgb evaluate(const Hit& hit, const Vec3& wo, const Vec3& wi) const = 0;
    virtual std::optional<BsdfSample> sample(const Hit& hit, const Vec3& wo, Point2 u) const = 0;
    virtual double pdf(const Hit& hit, const Vec3& wo, const Vec3& wi) const = 0;

    // Reflectance under uniform light: what an ambient light of radiance L adds to the surface is
    // ambient_reflectance · L (for Lambert, ρ: ∫ ρ/π · L cos θ dω = ρ·L).
    virtual Rgb ambient_reflectance(const Hit&) const { return {}; }
    // Radiance the surface emits towards wo.
    virtual Rgb emitted(const Hit&, const Vec3&) const { return {}; }

    // Absorption coefficient σ (per scene unit, per channel) of the medium this material encloses:
    // the hook for Beer's law. A ray that travels a distance d inside the object is attenuated by
    // beer_transmittance(σ, d) = exp(−σ d). The integrator applies it: when a ray meets a surface from
    // inside (dot(ray direction, hit.normal) > 0), it travelled d = hit.t · ‖ray direction‖ through that
    // surface's material. Zero (no absorption) for every material but dielectric.
    virtual Rgb absorption() const { return {}; }

    // True if sample() returns delta-flagged samples whose direction is random within the lobe (Ray
    // Tracing in One Weekend's fuzzy metal: no density to evaluate, so integrators treat it as a delta
    // lobe). Whitted must then follow one random sample instead of splitting into each delta lobe.
    virtual bool random_delta_direction() const { return false; }
};

// Beer–Lambert transmittance exp(−σ d) per channel after a distance d through a medium of absorption σ.
inline Rgb beer_transmittance(const Rgb& sigma, double distance) {
    return {std::exp(-sigma.r * distance), std::exp(-sigma.g * distance), std::exp(-sigma.b * distance)};
}

// The name → constructor table of materials ("matte", …).
using MaterialFactory = std::function<std::unique_ptr<Material>(Params&, const BuildContext&)>;
struct MaterialEntry {
    std::string name;
    MaterialFactory create;
};
const NameTable<MaterialEntry>& material_table();

// n flipped, if needed, to the side of v.
inline Vec3 face_forward(const Vec3& n, const Vec3& v) {
    return dot(n, v) < 0 ? -n : n;
}

// wo and wi strictly on the same side of the shading surface: a reflection, not a transmission.
inline bool same_hemisphere(const Hit& hit, const Vec3& wo, const Vec3& wi) {
    return dot(hit.shading_normal, wo) * dot(hit.shading_normal, wi) > 0;
}

// A cosine-weighted direction about +z (Malley's method: a uniform disk point lifted to the hemisphere);
// its density is z / π.
inline Vec3 sample_cosine_hemisphere(Point2 u) {
    const double r = std::sqrt(u.x);
    const double phi = 2 * kPi * u.y;
    return {r * std::cos(phi), r * std::sin(phi), safe_sqrt(1 - u.x)};
}

}  // namespace glint
