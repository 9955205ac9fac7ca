// `glint render model.obj`: an OBJ file as a whole scene, its MTL materials mapped to glint's
// (docs/importers.md, "OBJ and MTL").
#pragma once

#include <filesystem>

#include "glint/import/importer.hpp"
#include "glint/import/mtl.hpp"

namespace glint {

SceneDesc import_obj_scene(const std::filesystem::path& path, const ImportOptions& options);

// The glint material for an MTL material, as a {type: …} map; what it cannot keep is added to
// `warnings`. `base_dir` is the folder texture file names in the MTL resolve against, written relative
// to `scene_dir` (the imported scene's own folder).
Node material_from_mtl(const MtlMaterial& mtl, const std::filesystem::path& base_dir,
                       const std::filesystem::path& scene_dir, std::vector<SceneWarning>& warnings);

}  // namespace glint
