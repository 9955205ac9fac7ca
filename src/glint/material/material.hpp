// Materials: how a surface scatters light (paper §VI, VIII). Every material provides evaluate, sample
// and pdf of its BSDF, which must agree (the tests check it).
//
// Directions are world-space unit vectors pointing away from the surface: `wo` towards the viewer,
// `wi` towards the light. f(wo, wi) excludes the cosine factor.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/color.hpp"
#include "glint/geometry/hit.hpp"

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
};

// The name → constructor table of materials ("matte", …).
using MaterialFactory = std::function<std::unique_ptr<Material>(Params&, const BuildContext&)>;
struct MaterialEntry {
    std::string name;
    MaterialFactory create;
};
const std::vector<MaterialEntry>& material_table();

// n flipped, if needed, to the side of v.
inline Vec3 face_forward(const Vec3& n, const Vec3& v) {
    return dot(n, v) < 0 ? -n : n;
}

}  // namespace glint
