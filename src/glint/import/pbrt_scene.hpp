// `glint render scene.pbrt`: a pbrt-v4 scene as glint's scene tree (docs/import-pbrt.md).
#pragma once

#include <filesystem>
#include <string>

#include "glint/import/importer.hpp"

namespace glint {

SceneDesc import_pbrt_scene(const std::filesystem::path& path, const ImportOptions& options);

// The same for a scene's text held in memory (tests, the fuzz harness): files it names resolve against
// `base_dir`, and messages call it `display_path`.
SceneDesc import_pbrt_text(const std::string& text, const std::string& display_path,
                           const std::filesystem::path& base_dir);

}  // namespace glint
