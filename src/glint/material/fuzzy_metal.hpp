#pragma once

#include <memory>

#include "glint/material/material.hpp"
#include "glint/texture/texture.hpp"

namespace glint {

// Ray Tracing in One Weekend's metal (book 1, `metal::scatter`): the mirror direction R of the
// incoming ray, perturbed by `fuzz` times a uniformly random point s in the unit ball (the book's code
// at the commit bench/peers.py measures, random_in_unit_sphere) or on the unit sphere (`perturbation:
// sphere`, random_unit_vector, as later editions of the book have it),
//   scattered = R + fuzz · s,   |s| ≤ 1 (ball) or |s| = 1 (sphere),
// absorbed (sample() returns nullopt) when dot(scattered, N) ≤ 0 with N the normal facing the ray;
// otherwise the path is attenuated by `albedo` (no Fresnel term). With |R| = 1 and |fuzz · s| ≤ fuzz
// the scattered direction lies within the cone of half-angle asin(fuzz) about R.
//
// This lobe has no density that is easy to evaluate, so it is sampled as if it were a delta lobe:
// evaluate() and pdf() return 0 and sample() returns f = albedo / |cos θi|, pdf 1, delta = true (path
// weight albedo). Integrators therefore never light-sample it nor weight it by MIS; light reaches it only
// through sample(). That is exactly the book's estimator, whose only light is the sky that escaping
// BSDF-sampled rays see; under small lights it would converge (to the same image) but slowly.
// The random point is drawn in the shading frame's axes (the book's are the world's: the same
// distribution, as a uniform point on the sphere has no preferred axes). Looks up the albedo into
// MaterialPoint::specular.
class FuzzyMetal final : public Material {
  public:
    enum class Perturbation { Ball, Sphere };
    FuzzyMetal(std::shared_ptr<const Texture> albedo, double fuzz,
               Perturbation perturbation = Perturbation::Ball)
        : albedo_(std::move(albedo)), fuzz_(fuzz), perturbation_(perturbation) {}
    bool random_delta_direction() const override { return fuzz_ > 0; }

    static std::unique_ptr<Material> create(Params& params, const BuildContext& context);

  protected:
    MaterialPoint look_up(const Hit& hit) const override { return {{}, albedo_->evaluate(hit)}; }
    Rgb evaluate(const MaterialPoint&, const Vec3&, const Vec3&) const override { return {}; }
    std::optional<BsdfSample> sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const override;
    double pdf(const MaterialPoint&, const Vec3&, const Vec3&) const override { return 0; }

  private:
    std::shared_ptr<const Texture> albedo_;
    double fuzz_;
    Perturbation perturbation_;
};

}  // namespace glint
