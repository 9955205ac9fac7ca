#pragma once

#include "glint/integrator/integrator.hpp"

namespace glint {

class Material;
struct Hit;

// Whitted's model (1980; the paper §VI–VIII): at each surface the ambient term, direct light from every
// light with shadow rays (hard, or soft from lights with area and several samples), plus recursive
// perfect mirror reflection and refraction up to max_depth. A dielectric's two lobes are both traced,
// each weighted by its Fresnel share; light travelling inside an absorbing object falls off by Beer's
// law. Diffuse and glossy surfaces reflect only direct light. Since each dielectric hit doubles the
// rays, a branch whose weight in the pixel has fallen below kMinBranchWeight is not followed (Hall and
// Greenberg's adaptive depth control): the light it drops is under that weight times its radiance.
class WhittedIntegrator final : public Integrator {
  public:
    explicit WhittedIntegrator(int max_depth) : max_depth_(max_depth) {}
    Rgb radiance(const Scene& scene, const Ray& ray, SampleStream& samples, RayCounters& rays) const override;

  private:
    static constexpr double kMinBranchWeight = 1e-4;

    // `absorption`: σ_a of the medium the ray travels through (zero in air); `weight`: the largest
    // channel of the product of the lobe weights from the camera to here.
    Rgb trace(const Scene& scene, const Ray& ray, int depth, const Rgb& absorption, double weight,
              SampleStream& samples, RayCounters& rays) const;

    int max_depth_;
};

// Beer's law: the fraction of light left after `distance` in a medium of absorption σ_a.
Rgb beer_transmittance(const Rgb& absorption, double distance);

// σ_a of the medium a ray leaving `hit` in direction wi enters: the object's when wi crosses into it,
// air (zero) when it leaves, and `current` when it stays on the same side (reflection).
Rgb medium_after(const Material& material, const Hit& hit, const Vec3& wo, const Vec3& wi,
                 const Rgb& current);

}  // namespace glint
