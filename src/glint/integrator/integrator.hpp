// Integrators: the radiance arriving along a camera ray.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "glint/camera/camera.hpp"
#include "glint/core/color.hpp"
#include "glint/core/ray.hpp"
#include "glint/params/name_table.hpp"
#include "glint/sampling/sampler.hpp"

namespace glint {

struct World;
struct RenderSettings;
class Params;

// Rays traced, by kind; each tile keeps its own and the renderer adds them up.
struct RayCounters {
    std::uint64_t camera = 0;
    std::uint64_t shadow = 0;
    std::uint64_t secondary = 0;
    std::uint64_t total() const { return camera + shadow + secondary; }
    RayCounters& operator+=(const RayCounters& o) {
        camera += o.camera;
        shadow += o.shadow;
        secondary += o.secondary;
        return *this;
    }
};

class Integrator {
  public:
    virtual ~Integrator() = default;
    // Radiance arriving at the camera along `ray`, a camera ray: its direction is unit, as every
    // camera's is (camera.hpp). `samples` supplies this path's random numbers.
    virtual Rgb radiance(const World& world, const Ray& ray, SampleStream& samples,
                         RayCounters& rays) const = 0;
    // The radiances along several camera rays, each path with its own stream: out[i] is exactly
    // radiance(world, camera_rays[i], streams[i], rays). The render loop passes a batch's camera rays
    // together (up to 16: one pixel's pass, or whole neighbouring pixels'); by default they are traced one
    // after the other, and the path tracer traces all of their first rays before it follows any path on
    // (PathIntegrator::radiances says why).
    virtual void radiances(const World& world, std::span<const Ray> camera_rays,
                           std::span<SampleStream> streams, RayCounters& rays, std::span<Rgb> out) const {
        for (std::size_t i = 0; i < camera_rays.size(); ++i) {
            out[i] = radiance(world, camera_rays[i], streams[i], rays);
        }
    }

    // This integrator, readied for `world` seen through `camera` on a film of `film`'s size: what it
    // learns of the view before the first sample (the path tracer: where each light is seen, see
    // light_visibility.hpp). The render loop calls it once per render and traces every sample with the
    // result; nullptr when there is nothing to learn (then this integrator is used as it is). What is
    // learnt may change only the variance, never the expected radiance, and must be a pure function of
    // (world, camera, film size), so that images stay bit-identical for any threads or tiles.
    virtual std::unique_ptr<Integrator> prepared(const World& /*world*/, const Camera& /*camera*/,
                                                 FilmSize /*film*/) const {
        return nullptr;
    }
};

// An integrator reads its own parameters (`render: {integrator: {type: path, max_depth: 8}}`); the
// render settings give the defaults (`render.max_depth`, the short form's companion).
using IntegratorFactory = std::function<std::unique_ptr<Integrator>(Params&, const RenderSettings&)>;
struct IntegratorEntry {
    std::string name;
    std::string summary;
    IntegratorFactory create;
};
// The name → constructor table of integrators ("raycast", …).
const NameTable<IntegratorEntry>& integrator_table();

}  // namespace glint
