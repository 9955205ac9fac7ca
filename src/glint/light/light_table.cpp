// The one name → constructor table of lights. Adding a light: a file here and a line below.
#include "glint/light/ambient.hpp"
#include "glint/light/ambient_occlusion.hpp"
#include "glint/light/area.hpp"
#include "glint/light/directional.hpp"
#include "glint/light/environment.hpp"
#include "glint/light/point.hpp"
#include "glint/light/spot.hpp"

namespace glint {

const NameTable<LightEntry>& light_table() {
    static const NameTable<LightEntry> table = {
        {"ambient", &AmbientLight::create},
        {"point", &PointLight::create},
        {"spot", &SpotLight::create},
        {"directional", &DirectionalLight::create},
        {"area", &AreaLight::create},
        {"environment", &EnvironmentLight::create},
        {"ambient-occlusion", &AmbientOcclusionLight::create},
    };
    return table;
}

}  // namespace glint
