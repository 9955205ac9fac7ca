// Harnesses obj and ply: a mesh file through load_mesh_file (the loader `{type: mesh, file: …}` uses;
// for OBJ, load_obj with its mtllib and usemtl statements, as the OBJ importer calls it),
// then, if it loads, the Mesh shape the scene builder makes of it (normals repaired, BVH built) and a
// few rays through its bounds, as a render would trace.
//
// Findings: a crash, a leak, a hang, unbounded memory, an exception other than SceneError from the
// loader (or std::invalid_argument, "no triangle has an area", from the Mesh), or a loaded mesh whose
// indices, normals, texture coordinates or face materials do not match its vertices and faces.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string_view>

#include "fuzz_support.hpp"
#include "glint/geometry/mesh.hpp"

namespace {

void trace_through(const glint::Mesh& mesh) {
    const glint::Bounds3 box = mesh.bounds();
    const glint::Vec3 centre = (box.lo + box.hi) * 0.5;
    const glint::Vec3 extent = box.hi - box.lo;
    // From outside each face of the box (and one corner) towards the centre.
    const glint::Vec3 offsets[] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0},
                                   {0, 0, 1}, {0, 0, -1}, {1, 1, 1}};
    for (const glint::Vec3& offset : offsets) {
        const glint::Vec3 origin = centre + glint::hadamard(offset, extent + glint::Vec3{1, 1, 1});
        const glint::Ray ray{origin, centre - origin};
        glint::Hit hit;
        const bool hit_found = mesh.intersect(ray, std::numeric_limits<double>::infinity(), hit);
        if (hit_found) {
            GLINT_FUZZ_CHECK(hit.t > 0);
        }
        (void)mesh.occluded(ray, std::numeric_limits<double>::infinity());
    }
    if (mesh.area() > 0) {
        (void)mesh.sample_area({0.25, 0.75});
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const glint::fuzz::TemporaryInputFile input(GLINT_FUZZ_EXTENSION, data, size);
    const std::filesystem::path& path = input.path();
    glint::MeshData mesh_data;
    // An OBJ file is read as the OBJ importer reads it, with its materials.
    const bool obj = std::string_view(GLINT_FUZZ_EXTENSION) == ".obj";
    glint::ObjMaterialUse materials;
    try {
        mesh_data = obj ? glint::load_obj(path, {}, {}, &materials) : glint::load_mesh_file(path);
    } catch (const glint::SceneError& e) {
        glint::fuzz::check_scene_error(e);
        return 0;
    }
    if (obj) {
        GLINT_FUZZ_CHECK(materials.triangle_material.size() == mesh_data.triangles.size());
        for (const std::uint32_t material : materials.triangle_material) {
            GLINT_FUZZ_CHECK(material < materials.materials.size() ||
                             material == glint::ObjMaterialUse::kNoMaterial);
        }
    }
    GLINT_FUZZ_CHECK(mesh_data.uvs.empty() || mesh_data.uvs.size() == mesh_data.positions.size());
    GLINT_FUZZ_CHECK(mesh_data.normals.empty() || mesh_data.normals.size() == mesh_data.positions.size());
    for (const auto& triangle : mesh_data.triangles) {
        for (const std::uint32_t index : triangle) {
            GLINT_FUZZ_CHECK(index < mesh_data.positions.size());
        }
    }
    try {
        const glint::Mesh mesh(std::move(mesh_data));
        trace_through(mesh);
    } catch (const std::invalid_argument& e) {
        // No triangle with an area: Mesh::create reports it at the scene's `file:`.
        glint::fuzz::refused(e);
    }
    return 0;
}
