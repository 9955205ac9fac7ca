// Chooses the loader of a mesh file by its extension; reads files whole, after checking their size.
#include <algorithm>
#include <bit>
#include <fstream>
#include <limits>

#include "glint/geometry/mesh_io/mesh_data.hpp"

namespace glint {

static_assert(kMaxMeshCoordinate == static_cast<double>(std::numeric_limits<float>::max()));

namespace mesh_io {

std::string limit_text(std::uint64_t limit) {
    std::string text = std::to_string(limit);
    if (std::has_single_bit(limit) && limit >= 1024) {
        text += " (2^" + std::to_string(std::countr_zero(limit)) + ")";
    }
    return text;
}

std::string read_file(const std::filesystem::path& path, const SourcePos& mentioned_at,
                      std::uint64_t max_bytes) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) {
        throw SceneError(mentioned_at, "cannot read mesh file '" + path.string() + "': " + error.message());
    }
    if (size > max_bytes) {
        throw SceneError(mentioned_at, "mesh file '" + path.string() + "' is " + std::to_string(size) +
                                           " bytes, more than the limit of " + limit_text(max_bytes) +
                                           " bytes (mesh files are read whole into memory)");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw SceneError(mentioned_at, "cannot open mesh file '" + path.string() + "'");
    }
    std::string bytes(static_cast<std::size_t>(size), '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(size));
    if (in.bad() || static_cast<std::uintmax_t>(in.gcount()) != size) {
        throw SceneError(mentioned_at, "cannot read mesh file '" + path.string() +
                                           "' (it is shorter than its size said: did it change?)");
    }
    return bytes;
}

std::string lower_case_extension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

}  // namespace mesh_io

MeshData load_mesh_file(const std::filesystem::path& path, const SourcePos& mentioned_at,
                        const MeshLimits& limits) {
    const std::string extension = mesh_io::lower_case_extension(path);
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        throw SceneError(mentioned_at, "mesh file '" + path.string() +
                                           (std::filesystem::exists(path, error) ? "' is not a regular file"
                                                                                 : "' does not exist"));
    }
    if (extension == ".obj") {
        return load_obj(path, limits, mentioned_at);
    }
    if (extension == ".ply") {
        return load_ply(path, limits, mentioned_at);
    }
    throw SceneError(mentioned_at,
                     "mesh file '" + path.string() + "' has an unknown format (expected .obj or .ply)");
}

}  // namespace glint
