#pragma once

#include "glint/geometry/hit.hpp"
#include "glint/integrator/integrator.hpp"
#include "glint/material/material.hpp"

namespace glint {

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
    Rgb radiance(const World& world, const Ray& ray, SampleStream& samples, RayCounters& rays) const override;

  private:
    static constexpr double kMinBranchWeight = 1e-4;

    int max_depth_;
};

// Beer's law along a ray segment that ended at `hit`: a ray that meets a surface from inside
// (dot(direction, normal) > 0) crossed that surface's material, which keeps beer_transmittance of it,
// and `throughput` is multiplied by that. A segment through air leaves it untouched, with no
// multiplication by one. Inline: every path vertex asks, and nearly all arrive from outside (a call
// was 0.7 % of RTIOW's scene).
inline void attenuate_along_segment(Rgb& throughput, const Material& material, const Hit& hit,
                                    const Ray& ray) {
    if (dot(ray.direction, hit.normal) <= 0) {
        return;  // arrived from outside: the segment ran through air
    }
    const Rgb sigma = material.absorption();
    if (!sigma.is_black()) {
        throughput *= beer_transmittance(sigma, hit.t * length(ray.direction));
    }
}

}  // namespace glint
