// The one name → constructor table of shapes. Adding a shape: a file in this folder and a line here.
#include "glint/geometry/mesh.hpp"
#include "glint/geometry/plane.hpp"
#include "glint/geometry/sphere.hpp"

namespace glint {

const std::vector<ShapeEntry>& shape_table() {
    static const std::vector<ShapeEntry> table = {
        {"sphere", &Sphere::create},
        {"plane", &Plane::create},
        {"mesh", &Mesh::create},
    };
    return table;
}

}  // namespace glint
