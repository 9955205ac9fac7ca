// The one name → constructor table of materials. Adding a material: a file here and a line below.
#include "glint/material/dielectric.hpp"
#include "glint/material/emissive.hpp"
#include "glint/material/fuzzy_metal.hpp"
#include "glint/material/matte.hpp"
#include "glint/material/metal.hpp"
#include "glint/material/mirror.hpp"
#include "glint/material/phong.hpp"
#include "glint/material/plastic.hpp"
#include "glint/material/principled.hpp"

namespace glint {

const NameTable<MaterialEntry>& material_table() {
    static const NameTable<MaterialEntry> table = {
        {"matte", &Matte::create},
        {"phong", &Phong::create},
        {"plastic", &Plastic::create},
        {"mirror", &Mirror::create},
        {"metal", &Metal::create},
        {"glossy", &Metal::create},
        {"dielectric", &Dielectric::create},
        {"emissive", &Emissive::create},
        {"fuzzy-metal", &FuzzyMetal::create},
        {"principled", &Principled::create},
    };
    return table;
}

}  // namespace glint
