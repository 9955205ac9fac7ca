// The one name → constructor table of integrators. Adding one: a file here and a line below.
#include "glint/integrator/path.hpp"
#include "glint/integrator/raycast.hpp"
#include "glint/integrator/whitted.hpp"
#include "glint/world/settings.hpp"

namespace glint {

const std::vector<IntegratorEntry>& integrator_table() {
    static const std::vector<IntegratorEntry> table = {
        {"raycast", "direct light from every light with hard shadows; no reflection",
         [](const RenderSettings&) { return std::make_unique<RaycastIntegrator>(); }},
        {"whitted", "Whitted: direct light and shadows plus recursive mirror reflection and refraction",
         [](const RenderSettings& s) { return std::make_unique<WhittedIntegrator>(s.max_depth); }},
        {"path", "path tracing with next-event estimation and multiple importance sampling",
         [](const RenderSettings& s) { return std::make_unique<PathIntegrator>(s.max_depth); }},
    };
    return table;
}

std::unique_ptr<Integrator> make_integrator(const std::string& name, const RenderSettings& settings) {
    for (const IntegratorEntry& entry : integrator_table()) {
        if (entry.name == name) {
            return entry.create(settings);
        }
    }
    return nullptr;
}

std::vector<std::string> integrator_names() {
    std::vector<std::string> names;
    for (const IntegratorEntry& entry : integrator_table()) {
        names.push_back(entry.name);
    }
    return names;
}

}  // namespace glint
