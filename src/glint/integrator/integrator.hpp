// Integrators: the radiance arriving along a camera ray.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

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
    // Radiance arriving at the camera along `ray`. `samples` supplies this path's random numbers.
    virtual Rgb radiance(const World& world, const Ray& ray, SampleStream& samples,
                         RayCounters& rays) const = 0;
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
