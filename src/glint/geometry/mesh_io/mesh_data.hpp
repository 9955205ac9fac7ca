// A triangle mesh as read from a file, before it becomes a Shape: what the OBJ and PLY loaders return.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "glint/core/vec.hpp"
#include "glint/params/diagnostics.hpp"

namespace glint {

struct MeshData {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // empty, or one per position (possibly zero or NaN: the mesh fixes them)
    std::vector<Point2> uvs;    // empty, or one texture coordinate per position (v from the bottom up)
    // Empty, or one per position: x y z a tangent along increasing u, w ±1 the handedness, the
    // bitangent (along increasing v) being w · normal × tangent (glTF's TANGENT). Read only by meshes
    // with a normal map; the mesh computes them from the uvs when absent.
    std::vector<std::array<double, 4>> tangents;
    std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into positions, counter-clockwise
};

// What an OBJ file says about materials, for the OBJ importer (import/obj_scene.cpp) and for a mesh
// that takes only the faces of one material (`obj_material`). Read only when asked for.
struct ObjMaterialUse {
    struct Named {
        std::string name;
        SourcePos pos;  // the statement that names it (the first, for a material used more than once)
    };
    static constexpr std::uint32_t kNoMaterial = 0xffffffffu;  // faces before any `usemtl`
    std::vector<Named> libraries;                              // `mtllib` files, in file order
    std::vector<Named> materials;                  // `usemtl` names, distinct, in order of first use
    std::vector<std::uint32_t> triangle_material;  // per triangle: an index into materials, or kNoMaterial
};

// The largest mesh a file may describe. Every count read from a file is checked against these, and
// against what the rest of the file could hold, before anything is allocated from it; the default
// values are the documented limits (docs/scene-format.md), tests pass smaller ones.
struct MeshLimits {
    // 8 GiB. The file is read whole into memory; a binary PLY at the triangle limit takes about 5 GB.
    std::uint64_t max_file_bytes = std::uint64_t{1} << 33;
    // 2^28 = 268 435 456 vertices (after OBJ corners that differ in their normal are made separate
    // vertices), and as many triangles (after polygons are split into fans). Triangle, vertex, BVH leaf
    // and triangle-block numbers are 32-bit; 2^28 keeps them 16 times below overflow. A mesh takes
    // about 200 bytes per triangle once built, so the limit is already some 50 GB of memory.
    std::uint64_t max_vertices = std::uint64_t{1} << 28;
    std::uint64_t max_triangles = std::uint64_t{1} << 28;
};

// The largest coordinate a mesh vertex may have: float's largest value. The BVH stores its boxes in
// float, so a vertex beyond it could not be bounded; and it is surely a mistake in the file.
inline constexpr double kMaxMeshCoordinate = 3.4028234663852886e38;  // std::numeric_limits<float>::max()

// Reads an .obj or .ply file (chosen by the extension, case-insensitive). Every problem with the file
// is a SceneError positioned in it: file:line:col for text, a byte offset and element for binary data.
// `mentioned_at` is where the scene names the file, for errors about the file as a whole (missing,
// unknown extension, too large).
MeshData load_mesh_file(const std::filesystem::path& path, const SourcePos& mentioned_at = {},
                        const MeshLimits& limits = {});

// `materials`, when given, receives the file's `mtllib` and `usemtl` statements.
MeshData load_obj(const std::filesystem::path& path, const MeshLimits& limits = {},
                  const SourcePos& mentioned_at = {}, ObjMaterialUse* materials = nullptr);
MeshData load_ply(const std::filesystem::path& path, const MeshLimits& limits = {},
                  const SourcePos& mentioned_at = {});

namespace mesh_io {
// The whole file as bytes; a SceneError at `mentioned_at` if it cannot be read or is larger than
// `max_bytes` (its size is asked first, so nothing is allocated for a file that is too large).
std::string read_file(const std::filesystem::path& path, const SourcePos& mentioned_at,
                      std::uint64_t max_bytes);
// A file's extension in lower case, with its dot (".obj"): how files are told apart.
std::string lower_case_extension(const std::filesystem::path& path);
// "268435456 (2^28)": a limit as messages show it.
std::string limit_text(std::uint64_t limit);
}  // namespace mesh_io

}  // namespace glint
