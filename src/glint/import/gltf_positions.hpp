// A glTF file with the positions of its JSON text, for the importer's messages (docs/importers.md,
// "Where glTF messages point"): a .gltf's own lines and columns; for a .glb, the line and column in
// its JSON chunk, in a file named "model.glb (JSON chunk)" (the chunk begins at byte 20 of the file).
#pragma once

#include <filesystem>
#include <memory>

#include "glint/geometry/mesh_io/gltf_file.hpp"
#include "glint/import/json_positions.hpp"

namespace glint {

struct PositionedGltf {
    std::shared_ptr<const GltfFile> file;
    JsonPositions positions;
};

// load_gltf_file(path) and the positions of its JSON. A file tinygltf cannot read is a SceneError
// positioned as far as the reason allows: malformed JSON where it stops being JSON; a reason that
// names an element ("image[3]") at that element; a property missing from an element of a section
// ("'byteLength' property is missing in Buffer") at the first element of the section without it
// (tinygltf stops at the first); a reason that names a section ("Invalid `componentType` in
// accessor") at the section; anything else at `whole_file`.
PositionedGltf load_positioned_gltf(const std::filesystem::path& path, const SourcePos& whole_file);

}  // namespace glint
