// Materials: how a surface scatters light (paper §VI, VIII).
//
// A material is evaluated once per hit into a Bsdf (pbrt-v4's Material::GetBSDF, Yocto/GL's
// eval_material then eval_bsdf): Material::bsdf(hit) looks the material's textures up once, into a
// MaterialPoint, and pairs them with the shading frame at the hit. The Bsdf's evaluate, sample, pdf
// and ambient_reflectance then read no texture, however often an integrator asks at that hit
// (next-event estimation, its MIS weight, the next bounce, Whitted's lobe probes). Each material
// writes evaluate, sample and pdf, which must agree (the tests check it).
//
// Directions point away from the surface: `wo` towards the viewer, `wi` towards the light. f(wo, wi)
// excludes the cosine factor. Either may lie on either side of the surface (hit.normal points out of
// closed shapes; a ray inside glass sees wo below it). The Bsdf takes and returns world-space unit
// vectors and turns them once into the shading frame, in which materials write their lobes: z is the
// shading normal, not turned towards wo, so cos θ = w.z, and w.z < 0 below the surface.
//
// Lambert's lobe of a constant albedo, the most common surface, also has a BSDF value of its own,
// LambertBsdf, with no virtual call, which the path tracer uses where Material::constant_lambert() says
// it may.
//
// A sample's path weight is f · |cos θi| / pdf with cos θi = dot(hit.shading_normal, wi) (absolute:
// transmitted directions lie on the other side); the sample carries it (BsdfSample::weight), in closed
// form where the lobe has one. For delta lobes (mirror, smooth glass, the coat of
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
#include "glint/core/frame.hpp"
#include "glint/geometry/hit.hpp"
#include "glint/params/name_table.hpp"

namespace glint {

class Params;
struct BuildContext;
class Bsdf;

// A direction sampled from a BSDF, made by a material's sample() in its shading frame (z the shading
// normal), where the sample's weight is computed.
struct BsdfSample {
    // The weight f · |cos θi| / pdf from the others (cos θi = wi.z: wi in the shading frame).
    BsdfSample(const Vec3& direction, const Rgb& value, double density, bool is_delta)
        : BsdfSample(direction, value, density, is_delta,
                     density > 0 ? value * (std::abs(direction.z) / density) : Rgb{}) {}
    // The weight in closed form, where the lobe has one: what f · |cos θi| / pdf comes to once its
    // factors cancel (Lambert's ρ, a mirror's reflectance), without their rounding, and without the
    // division on the way from one bounce to the next (Mitsuba's BSDF::sample returns it too).
    BsdfSample(const Vec3& direction, const Rgb& value, double density, bool is_delta, const Rgb& path_weight)
        : wi(direction), f(value), pdf(density), delta(is_delta), weight(path_weight) {}

    Vec3 wi;
    Rgb f;               // BSDF value for (wo, wi)
    double pdf = 0;      // solid-angle density of wi; for a delta lobe, the discrete probability
    bool delta = false;  // a mirror or refraction direction: f and pdf are Dirac weights
    // f · |cos θi| / pdf: the factor by which the sample carries a path's throughput on (zero when
    // pdf is not positive).
    Rgb weight;
};

// Helpers for lobes in the shading frame (z the shading normal).

// wo and wi strictly on the same side of the surface: a reflection, not a transmission.
inline bool same_hemisphere(const Vec3& wo, const Vec3& wi) {
    return wo.z * wi.z > 0;
}

// The mirror direction of wo about the shading normal, on either side: R = 2(wo·N)N − wo.
inline Vec3 mirror_local(const Vec3& wo) {
    return {-wo.x, -wo.y, wo.z};
}

// w with its z negated when side < 0: the surface seen from its other side. A two-sided lobe written for
// wo above the surface serves wo below through flip_if_below(wo, wo.z) and flip_if_below(wi, wo.z).
inline Vec3 flip_if_below(const Vec3& w, double side) {
    return side < 0 ? Vec3{w.x, w.y, -w.z} : w;
}

// A cosine-weighted direction about +z (Malley's method: a uniform disk point lifted to the hemisphere);
// its density is z / π.
inline Vec3 sample_cosine_hemisphere(Point2 u) {
    const double r = std::sqrt(u.x);
    const SinCos phi = sincos_turns(u.y);
    return {r * phi.cos, r * phi.sin, safe_sqrt(1 - u.x)};
}

// Lambert's lobe of reflectance ρ in the shading frame, on wo's side: f = ρ/π. Matte is this lobe alone,
// and LambertBsdf evaluates it inline (see Material::constant_lambert).
inline Rgb lambert_evaluate(const Rgb& rho, const Vec3& wo, const Vec3& wi) {
    return same_hemisphere(wo, wi) ? rho * kInvPi : Rgb{};
}
inline double lambert_pdf(const Vec3& wo, const Vec3& wi) {
    return same_hemisphere(wo, wi) ? std::abs(wi.z) * kInvPi : 0;
}
inline std::optional<BsdfSample> lambert_sample(const Rgb& rho, const Vec3& wo, Point2 u) {
    // Cosine-weighted about the normal on wo's side.
    const Vec3 wi = sample_cosine_hemisphere(u);
    const double pdf = wi.z * kInvPi;
    if (pdf <= 0) {
        return std::nullopt;
    }
    // f · cos θ / pdf = (ρ/π) · cos θ / (cos θ/π) = ρ.
    return BsdfSample{flip_if_below(wi, wo.z), rho * kInvPi, pdf, false, rho};
}

// What a material's textures give at one hit (Yocto/GL's material_point): the parameters of its BSDF
// that vary over the surface, looked up once. Each material says which fields it fills; the others stay
// black (zero). A small fixed struct rather than a variant of per-material lobe types: every Material
// subclass, the tests' stand-ins included, writes its own lobes with no central list to extend, and the
// Bsdf stays a plain value (no allocation per hit).
struct MaterialPoint {
    // Reflectance of a diffuse part: matte albedo, phong kd, the base of plastic, principled's
    // (1 − metallic) · base colour.
    Rgb diffuse;
    // Reflectance of a specular or glossy part: phong ks, mirror kr, metal F₀, fuzzy albedo, principled's
    // metallic · base colour (the metal's share of F₀).
    Rgb specular;
    double metallic = 0;  // principled: the share of the metal lobe, in [0, 1]
    double alpha = 0;     // principled: the GGX width α of the specular lobe (roughness²)
};

class Material {
  public:
    virtual ~Material() = default;

    // The BSDF at `hit`: the textures looked up once, in the shading frame about hit.shading_normal.
    Bsdf bsdf(const Hit& hit) const;
    // The reflectance ρ of a material whose BSDF is Lambert's lobe alone, ρ constant (Matte without a
    // texture); nullptr for any other. Its BSDF at a hit is then LambertBsdf(frame, ρ), which a caller
    // may use instead of bsdf(): the same values, without the virtual calls of look_up, evaluate,
    // sample and pdf at every vertex.
    const Rgb* constant_lambert() const { return constant_lambert_ ? &*constant_lambert_ : nullptr; }

    // Radiance the surface emits towards wo (world space).
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

  protected:
    friend class Bsdf;

    // Called by a material whose BSDF is Lambert's lobe alone, of a constant reflectance (Matte without a
    // texture): see constant_lambert(). Its own evaluate, sample and pdf must still be that lobe's
    // (Matte's call lambert_evaluate, lambert_sample and lambert_pdf, as LambertBsdf does).
    void set_constant_lambert(const Rgb& albedo) { constant_lambert_ = albedo; }

    // The textures at `hit`; bsdf() calls it once per hit.
    virtual MaterialPoint look_up(const Hit&) const { return {}; }

    // The BSDF in the local shading frame (z the shading normal, cos θ = w.z), at a looked-up point.
    virtual Rgb evaluate(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const = 0;
    virtual std::optional<BsdfSample> sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const = 0;
    virtual double pdf(const MaterialPoint& point, const Vec3& wo, const Vec3& wi) const = 0;

    // Reflectance under uniform light: what an ambient light of radiance L adds to the surface is
    // ambient_reflectance · L (for Lambert, ρ: ∫ ρ/π · L cos θ dω = ρ·L).
    virtual Rgb ambient_reflectance(const MaterialPoint&) const { return {}; }

  private:
    std::optional<Rgb> constant_lambert_;
};

// A material's BSDF at one hit: the material, its looked-up textures and the shading frame. A small
// value made per hit and used there (it refers to its material, which outlives it).
class Bsdf {
  public:
    Bsdf(const Material& material, const Frame& frame, const MaterialPoint& point)
        : material_(&material), frame_(frame), point_(point) {}

    // World space: wo and wi are turned into the shading frame once per call, a sample's wi back.
    Rgb evaluate(const Vec3& wo, const Vec3& wi) const {
        return evaluate_local(frame_.to_local(wo), frame_.to_local(wi));
    }
    std::optional<BsdfSample> sample(const Vec3& wo, Point2 u) const {
        return sample_from_local(frame_.to_local(wo), u);
    }
    // sample(), from wo already in the shading frame (for a caller that turns it once for several calls);
    // the sample's wi in world space.
    std::optional<BsdfSample> sample_from_local(const Vec3& wo_local, Point2 u) const {
        std::optional<BsdfSample> s = sample_local(wo_local, u);
        if (s) {
            s->wi = frame_.to_world(s->wi);
        }
        return s;
    }
    double pdf(const Vec3& wo, const Vec3& wi) const {
        return pdf_local(frame_.to_local(wo), frame_.to_local(wi));
    }
    // Reflectance under uniform light (see Material::ambient_reflectance).
    Rgb ambient_reflectance() const { return material_->ambient_reflectance(point_); }

    // The same in the shading frame: z is the shading normal.
    Rgb evaluate_local(const Vec3& wo, const Vec3& wi) const { return material_->evaluate(point_, wo, wi); }
    std::optional<BsdfSample> sample_local(const Vec3& wo, Point2 u) const {
        return material_->sample(point_, wo, u);
    }
    double pdf_local(const Vec3& wo, const Vec3& wi) const { return material_->pdf(point_, wo, wi); }

    const Frame& frame() const { return frame_; }
    // What the textures gave at the hit (the albedo AOV reads its reflectances).
    const MaterialPoint& point() const { return point_; }

  private:
    const Material* material_;
    Frame frame_;
    MaterialPoint point_;
};

inline Bsdf Material::bsdf(const Hit& hit) const {
    return Bsdf(*this, Frame::from_normal(hit.shading_normal), look_up(hit));
}

// Lambert's lobe of a constant reflectance ρ at one hit, with the Bsdf's interface in the shading
// frame: what the Bsdf of a Material::constant_lambert() material computes, inline. For callers
// written once for both (templates on the BSDF's type: the path tracer's vertex). A class of its own,
// a frame and a colour, rather than a flag in Bsdf that its calls test: with the flag, the Cornell box
// ran 3.6 % fewer instructions and took the same time (the Bsdf's material point and pointer still
// built and carried); with this, 5.1 % fewer and 0.97 of the time.
class LambertBsdf {
  public:
    LambertBsdf(const Frame& frame, const Rgb& rho) : frame_(frame), rho_(rho) {}

    Rgb evaluate_local(const Vec3& wo, const Vec3& wi) const { return lambert_evaluate(rho_, wo, wi); }
    double pdf_local(const Vec3& wo, const Vec3& wi) const { return lambert_pdf(wo, wi); }
    std::optional<BsdfSample> sample_from_local(const Vec3& wo_local, Point2 u) const {
        std::optional<BsdfSample> s = lambert_sample(rho_, wo_local, u);
        if (s) {
            s->wi = frame_.to_world(s->wi);
        }
        return s;
    }
    const Frame& frame() const { return frame_; }

  private:
    Frame frame_;
    Rgb rho_;
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

}  // namespace glint
