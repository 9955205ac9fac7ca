// The one name → constructor table of materials. Adding a material: a file here and a line below.
#include "glint/material/matte.hpp"

namespace glint {

const std::vector<MaterialEntry>& material_table() {
    static const std::vector<MaterialEntry> table = {
        {"matte", &Matte::create},
    };
    return table;
}

}  // namespace glint
