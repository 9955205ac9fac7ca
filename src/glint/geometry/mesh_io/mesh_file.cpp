// Chooses the loader of a mesh file by its extension.
#include <algorithm>
#include <fstream>
#include <sstream>

#include "glint/geometry/mesh_io/mesh_data.hpp"

namespace glint {

namespace mesh_io {
std::string read_file(const std::filesystem::path& path, const SourcePos& mentioned_at) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw SceneError(mentioned_at, "cannot open mesh file '" + path.string() + "'");
    }
    std::ostringstream bytes;
    bytes << in.rdbuf();
    if (in.bad()) {
        throw SceneError(mentioned_at, "cannot read mesh file '" + path.string() + "'");
    }
    return std::move(bytes).str();
}
}  // namespace mesh_io

MeshData load_mesh_file(const std::filesystem::path& path, const SourcePos& mentioned_at) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (!std::filesystem::is_regular_file(path)) {
        throw SceneError(mentioned_at, "mesh file '" + path.string() + "' does not exist");
    }
    if (extension == ".obj") {
        return load_obj(path);
    }
    if (extension == ".ply") {
        return load_ply(path);
    }
    throw SceneError(mentioned_at,
                     "mesh file '" + path.string() + "' has an unknown format (expected .obj or .ply)");
}

}  // namespace glint
