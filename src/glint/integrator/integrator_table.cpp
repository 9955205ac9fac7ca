// The one name → constructor table of integrators. Adding one: a file here and a line below.
#include "glint/integrator/path.hpp"
#include "glint/integrator/raycast.hpp"
#include "glint/integrator/whitted.hpp"
#include "glint/params/params.hpp"
#include "glint/world/settings.hpp"

namespace glint {

namespace {

// The integrator's own `max_depth`, or the render block's. Within 1 … kMaxPathDepth (settings.hpp).
int max_depth(Params& p, const RenderSettings& settings) {
    const std::int64_t depth = p.positive_integer("max_depth", settings.max_depth);
    if (depth > kMaxPathDepth) {
        p.fail("max_depth", max_depth_limit_message(p.what() + ".max_depth"));
    }
    return static_cast<int>(depth);
}

}  // namespace

const NameTable<IntegratorEntry>& integrator_table() {
    static const NameTable<IntegratorEntry> table = {
        {"raycast", "direct light from every light with hard shadows; no reflection",
         [](Params&, const RenderSettings&) { return std::make_unique<RaycastIntegrator>(); }},
        {"whitted", "Whitted: direct light and shadows plus recursive mirror reflection and refraction",
         [](Params& p, const RenderSettings& s) {
             return std::make_unique<WhittedIntegrator>(max_depth(p, s));
         }},
        {"path", "path tracing with next-event estimation and multiple importance sampling",
         [](Params& p, const RenderSettings& s) {
             const int depth = max_depth(p, s);
             PathOptions options;
             options.sample_lights = p.boolean("sample_lights", true);
             options.learn_light_visibility = p.boolean("learn_light_visibility", true);
             return std::make_unique<PathIntegrator>(depth, options);
         }},
    };
    return table;
}

}  // namespace glint
