// glTF 2.0 files (.gltf with its buffers, or .glb), read through Debian's tinygltf: the parsed model,
// shared by the glTF importer (import/gltf_scene.cpp, which reads nodes, cameras, materials and
// lights) and by meshes that take one primitive of it ({type: mesh, file: x.gltf, gltf_mesh: M,
// gltf_primitive: P}).
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "glint/geometry/mesh_io/mesh_data.hpp"
#include "glint/image/image.hpp"

namespace tinygltf {
class Model;
}

namespace glint {

class Params;
struct BuildContext;

struct GltfFile {
    std::string path;
    std::shared_ptr<const tinygltf::Model> model;
    std::shared_ptr<const SourceFile> source;  // the JSON text, for positions (empty for .glb)
};

// The largest glTF file, and the largest external buffer it may refer to: 2 GiB each.
inline constexpr std::uint64_t kMaxGltfFileBytes = std::uint64_t{1} << 31;

// Reads a .gltf or .glb file and the buffers it refers to (relative to its folder; data: URIs too).
// Images are not decoded here: an image texture reads its file itself, or decodes the bytes of one
// stored in the model (gltf_image_bytes). The last file read is kept
// (path, size and modification time must match), so the meshes of a model's primitives, built one
// after another, read it once; forget_gltf_files() lets it go. A file tinygltf cannot read is a
// SceneError at `mentioned_at` with tinygltf's reason.
std::shared_ptr<const GltfFile> load_gltf_file(const std::filesystem::path& path,
                                               const SourcePos& mentioned_at);
void forget_gltf_files();

// The triangles of primitive `primitive` of mesh `mesh`: POSITION, NORMAL and TEXCOORD_0 (glTF's v
// runs down an image, glint's up: v becomes 1 − v) and the indices (or none: consecutive triples).
// Every accessor is checked against its buffer view and buffer before it is read; a primitive that
// is not made of triangles (points, lines, strips and fans are split) or refers to a missing accessor
// is a SceneError at `mentioned_at`.
// How many primitives mesh `mesh` has; a SceneError at `mentioned_at` when there is no such mesh.
int gltf_primitive_count(const GltfFile& file, int mesh, const SourcePos& mentioned_at);

MeshData gltf_primitive_mesh(const GltfFile& file, int mesh, int primitive, const SourcePos& mentioned_at);

// The encoded bytes (PNG, JPEG, …) of image `image` when the file holds it (a buffer view or a data:
// URI); a SceneError at `mentioned_at` when it has no such image or the image is a file of its own.
const std::vector<unsigned char>& gltf_image_bytes(const GltfFile& file, int image,
                                                   const SourcePos& mentioned_at);

// The image a scene map names by its keys `file` (an image file, resolved against the scene file's
// folder) and, with a .gltf or .glb `file`, `gltf_image: N` (the model's image N stored inside it): what
// image textures and normal maps read. `srgb` as read_image's. A missing, unreadable, oversized or empty
// image is a SceneError at `file` (or at `gltf_image`).
Image read_image_keys(Params& params, const BuildContext& context, bool srgb);

}  // namespace glint
