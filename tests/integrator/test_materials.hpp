// Minimal materials for the integrator tests, standing in for (and independent of) the material
// library: a Lambertian surface that also emits, a perfect mirror and a smooth glass.
#pragma once

#include "glint/material/material.hpp"

namespace glint::test {

// ρ/π reflection plus Lₑ emitted from both sides.
class EmittingMatte final : public Material {
  public:
    EmittingMatte(const Rgb& albedo, const Rgb& emission) : albedo_(albedo), emission_(emission) {}
    Rgb emitted(const Hit&, const Vec3&) const override { return emission_; }

  protected:
    Rgb evaluate(const MaterialPoint&, const Vec3& wo, const Vec3& wi) const override {
        return wo.z * wi.z > 0 ? albedo_ * kInvPi : Rgb{};
    }
    std::optional<BsdfSample> sample(const MaterialPoint&, const Vec3& wo, Point2 u) const override {
        const double r = std::sqrt(u.x);
        const double phi = 2 * kPi * u.y;
        const double z = safe_sqrt(1 - u.x);
        if (z <= 0) {
            return std::nullopt;
        }
        const Vec3 wi{r * std::cos(phi), r * std::sin(phi), wo.z < 0 ? -z : z};
        return BsdfSample{wi, albedo_ * kInvPi, z * kInvPi, false};
    }
    double pdf(const MaterialPoint&, const Vec3& wo, const Vec3& wi) const override {
        return wo.z * wi.z > 0 ? std::abs(wi.z) * kInvPi : 0;
    }
    Rgb ambient_reflectance(const MaterialPoint&) const override { return albedo_; }

  private:
    Rgb albedo_, emission_;
};

// Reflects everything into the mirror direction: f = δ/|cos θ|, pdf 1.
class PerfectMirror final : public Material {
  protected:
    Rgb evaluate(const MaterialPoint&, const Vec3&, const Vec3&) const override { return {}; }
    std::optional<BsdfSample> sample(const MaterialPoint&, const Vec3& wo, Point2) const override {
        const Vec3 n{0, 0, wo.z < 0 ? -1.0 : 1.0};
        const Vec3 wi = reflect(-wo, n);
        return BsdfSample{wi, Rgb(1.0 / std::abs(wi.z)), 1.0, true};
    }
    double pdf(const MaterialPoint&, const Vec3&, const Vec3&) const override { return 0; }
};

// Smooth glass of index η with exact Fresnel reflectance; chooses reflection with probability F
// (u.x < F), so pdf is F or 1 − F and f·|cos|/pdf = 1 (no radiance scaling by η²: importance-neutral
// enough for these tests, whose light paths cross the glass twice). Optional Beer absorption.
class SmoothGlass final : public Material {
  public:
    SmoothGlass(double eta, const Rgb& absorption) : eta_(eta), absorption_(absorption) {}
    Rgb absorption() const override { return absorption_; }

    static double fresnel(double cos_i, double eta) {  // eta = n_t / n_i
        const double sin2_t = (1 - cos_i * cos_i) / (eta * eta);
        if (sin2_t >= 1) {
            return 1;
        }
        const double cos_t = std::sqrt(1 - sin2_t);
        const double rs = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
        const double rp = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
        return 0.5 * (rs * rs + rp * rp);
    }

  protected:
    Rgb evaluate(const MaterialPoint&, const Vec3&, const Vec3&) const override { return {}; }
    double pdf(const MaterialPoint&, const Vec3&, const Vec3&) const override { return 0; }
    std::optional<BsdfSample> sample(const MaterialPoint&, const Vec3& wo, Point2 u) const override {
        const bool entering = wo.z > 0;
        const Vec3 n{0, 0, entering ? 1.0 : -1.0};
        const double eta = entering ? eta_ : 1 / eta_;
        const double cos_i = dot(n, wo);
        const double f = fresnel(cos_i, eta);
        if (u.x < f) {
            const Vec3 wi = reflect(-wo, n);
            return BsdfSample{wi, Rgb(f / cos_i), f, true};
        }
        const double ratio = 1 / eta;  // n_i / n_t
        const double k = 1 - ratio * ratio * (1 - cos_i * cos_i);
        const Vec3 wi = normalize(-wo * ratio + n * (ratio * cos_i - std::sqrt(k)));
        return BsdfSample{wi, Rgb((1 - f) / std::abs(wi.z)), 1 - f, true};
    }

  private:
    double eta_;
    Rgb absorption_;
};

}  // namespace glint::test
