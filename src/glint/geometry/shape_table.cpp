// The one name → constructor table of shapes. Adding a shape: a file in this folder and a line here.
#include "glint/geometry/box.hpp"
#include "glint/geometry/cone.hpp"
#include "glint/geometry/cylinder.hpp"
#include "glint/geometry/disk.hpp"
#include "glint/geometry/mesh.hpp"
#include "glint/geometry/plane.hpp"
#include "glint/geometry/rectangle.hpp"
#include "glint/geometry/sphere.hpp"
#include "glint/geometry/torus.hpp"

namespace glint {

const NameTable<ShapeEntry>& shape_table() {
    // One entry a line, so that adding a shape is a one-line change.
    // clang-format off
    static const NameTable<ShapeEntry> table = {
        {"sphere", &Sphere::create},
        {"plane", &Plane::create},
        {"disk", &Disk::create},
        {"annulus", &Disk::create_annulus},
        {"rectangle", &Rectangle::create},
        {"box", &Box::create},
        {"cylinder", &Cylinder::create},
        {"cone", &Cone::create},
        {"torus", &Torus::create},
        {"mesh", &Mesh::create},
    };
    // clang-format on
    return table;
}

}  // namespace glint
