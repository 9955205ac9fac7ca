// A triangle mesh as read from a file, before it becomes a Shape: what the OBJ and PLY loaders return.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "glint/core/vec.hpp"
#include "glint/scene/diagnostics.hpp"

namespace glint {

struct MeshData {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // empty, or one per position (possibly zero or NaN: the mesh fixes them)
    std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into positions, counter-clockwise
};

// Reads an .obj or .ply file (chosen by the extension, case-insensitive). Every problem with the file
// is a SceneError positioned in it: file:line:col for text, a byte offset and element for binary data.
// `mentioned_at` is where the scene names the file, for errors about the file as a whole (missing,
// unknown extension).
MeshData load_mesh_file(const std::filesystem::path& path, const SourcePos& mentioned_at = {});

MeshData load_obj(const std::filesystem::path& path);
MeshData load_ply(const std::filesystem::path& path);

namespace mesh_io {
// The whole file as bytes; a SceneError at `mentioned_at` if it cannot be read.
std::string read_file(const std::filesystem::path& path, const SourcePos& mentioned_at = {});
}  // namespace mesh_io

}  // namespace glint
