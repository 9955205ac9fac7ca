#pragma once

#include "glint/integrator/integrator.hpp"

namespace glint {

// Unidirectional path tracing of the rendering equation (Kajiya 1986; pbrt-v4 §13.4). At each vertex:
// next-event estimation (one sample of every physical light, with a shadow ray) and a BSDF-sampled
// continuation; light reached by both strategies — area lights and the environment — is weighed by
// the power heuristic (Veach's multiple importance sampling, β = 2), so neither small bright lights
// nor large dim ones are noisy. Delta lights are reached only by light sampling, delta lobes (mirror,
// glass) only by BSDF sampling, each with full weight. After 3 bounces, Russian roulette ends a path whose
// throughput has fallen below 1/4 with probability 1 − 4 · max throughput. Beer's law along rays inside
// absorbing objects. max_depth counts bounces: 1 is direct light only. Ambient and ambient-occlusion lights
// are left out (they stand in for the indirect light the path tracer computes).
class PathIntegrator final : public Integrator {
  public:
    explicit PathIntegrator(int max_depth) : max_depth_(max_depth) {}
    Rgb radiance(const World& world, const Ray& ray, SampleStream& samples, RayCounters& rays) const override;

  private:
    int max_depth_;
};

// Veach's power heuristic (β = 2) for one sample from each of two strategies.
inline double power_heuristic(double pdf_a, double pdf_b) {
    const double a = pdf_a * pdf_a;
    const double b = pdf_b * pdf_b;
    return a + b > 0 ? a / (a + b) : 0;
}

}  // namespace glint
