#pragma once

#include "glint/integrator/integrator.hpp"
#include "glint/integrator/light_visibility.hpp"

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
//
// Sphere lights that the view sees only in part (smallpt's, buried in its ceiling) are sampled with
// what LightVisibility learns before the first sample (`learn_light_visibility`, on by default).
//
// With `sample_lights` off it is the estimator of smallpt and of the RTIOW books: no light sample and no
// shadow ray, light found only where a BSDF sample hits an emitter or escapes to the sky, and counted
// in full there. It converges to the same image (delta lights aside, which nothing hits), with more
// noise per sample for less work per sample: the way to compare glint with those renderers sample for
// sample, and to see what next-event estimation buys.
struct PathOptions {
    bool sample_lights = true;           // next-event estimation, weighed against BSDF sampling by MIS
    bool learn_light_visibility = true;  // used only when sample_lights is on
};

class PathIntegrator final : public Integrator {
  public:
    explicit PathIntegrator(int max_depth, PathOptions options = {})
        : max_depth_(max_depth), options_(options) {}
    Rgb radiance(const World& world, const Ray& ray, SampleStream& samples, RayCounters& rays) const override;
    // All the camera rays first, handed to the accelerator together, then each path on from its first
    // hit. Rays of one pixel, or of neighbouring pixels, take nearly the same way through the scene's
    // BVH: traced one after the other, the later ones find the branches of that way predicted and their
    // nodes in cache (RTIOW's final scene in 0.945 of the time); an accelerator that traces packets
    // walks the tree once for them all. With such an accelerator the paths' first bounces go together
    // too (path.cpp says why); their later bounces go every way, and interleaving those (paths in
    // lockstep) made no scene faster. Each path gets radiance()'s bits (docs/benchmarks.md).
    void radiances(const World& world, std::span<const Ray> camera_rays, std::span<SampleStream> streams,
                   RayCounters& rays, std::span<Rgb> out) const override;
    // A copy that samples the sphere lights with what LightVisibility learns of this view; nullptr
    // when learning is off or finds nothing to favour.
    std::unique_ptr<Integrator> prepared(const World& world, const Camera& camera,
                                         FilmSize film) const override;
    // What the copy made by prepared() learnt (nullptr for this integrator as built).
    const LightVisibility* light_visibility() const { return visibility_.get(); }
    // Whether each vertex samples the lights (next-event estimation); off, only BSDF samples find light.
    bool samples_lights() const { return options_.sample_lights; }

  private:
    // One path's state from bounce to bounce (path.cpp).
    struct Path;
    // radiances() follows paths this many at a time (the render loop hands at most 16).
    static constexpr std::size_t kPathsTogether = 16;
    // The nearest hit of the path's ray, into its current Hit.
    void trace(const World& world, Path& path) const;
    // The same for up to kPathsTogether paths, their rays handed to the accelerator together
    // (World::intersect_packet): each path gets the hit trace() would give it.
    void trace_together(const World& world, std::span<Path* const> paths) const;
    // What the path's current hit adds to its radiance, and its next ray: false when the path ends.
    bool shade(const World& world, Path& path, RayCounters& rays) const;
    // shade()'s next-event estimation and next bounce, once the BSDF at the hit is made (a Bsdf, or a
    // LambertBsdf for a material with a constant Lambert lobe).
    template <class BsdfAtHit>
    bool scatter(const World& world, Path& path, RayCounters& rays, const BsdfAtHit& bsdf,
                 const Vec3& wo) const;
    // Light::sample and Light::pdf of world.lights[index], with what was learnt of it.
    std::optional<LightSample> light_sample_of(const World& world, std::size_t index, const Hit& at,
                                               Point2 u) const;
    double light_pdf_of(const World& world, std::size_t index, const Hit& at, const Vec3& wi,
                        const Hit* on_light) const;

    int max_depth_;
    PathOptions options_;
    std::shared_ptr<const LightVisibility> visibility_;  // shared by copies; never changed once learnt
};

// Veach's power heuristic (β = 2) for one sample from each of two strategies.
inline double power_heuristic(double pdf_a, double pdf_b) {
    const double a = pdf_a * pdf_a;
    const double b = pdf_b * pdf_b;
    return a + b > 0 ? a / (a + b) : 0;
}

// power_heuristic(pdf_a, pdf_b) / pdf_a = pdf_a / (pdf_a² + pdf_b²), for an estimator that divides by
// pdf_a anyway (next-event estimation): one division instead of two.
inline double power_heuristic_over_pdf(double pdf_a, double pdf_b) {
    const double sum = pdf_a * pdf_a + pdf_b * pdf_b;
    return sum > 0 ? pdf_a / sum : 0;
}

}  // namespace glint
