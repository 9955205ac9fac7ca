// `glint render model.gltf` (or .glb): a glTF 2.0 scene — its node hierarchy, meshes, metallic-
// roughness materials, the first camera (or --camera NAME) and KHR_lights_punctual lights — as a glint
// scene (docs/importers.md, "glTF 2.0").
#pragma once

#include <filesystem>

#include "glint/import/importer.hpp"

namespace glint {

SceneDesc import_gltf_scene(const std::filesystem::path& path, const ImportOptions& options);

}  // namespace glint
