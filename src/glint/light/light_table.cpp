// The one name → constructor table of lights. Adding a light: a file here and a line below.
#include "glint/light/ambient.hpp"
#include "glint/light/point.hpp"

namespace glint {

const std::vector<LightEntry>& light_table() {
    static const std::vector<LightEntry> table = {
        {"ambient", &AmbientLight::create},
        {"point", &PointLight::create},
    };
    return table;
}

}  // namespace glint
