// The parsed, format-independent description of a scene: step one of scene file → SceneDesc → Scene.
#pragma once

#include <filesystem>
#include <string>

#include "glint/scene/node.hpp"

namespace glint {

struct SceneDesc {
    Node root;                       // the top-level map: render, camera, materials, objects, lights, …
    std::filesystem::path base_dir;  // relative paths inside the scene resolve against this folder
};

// Parses YAML (and so JSON) text. `display_path` names the file in error messages.
// Throws SceneError on a syntax error, a duplicate key or a top level that is not a map.
SceneDesc parse_scene_text(const std::string& text, const std::string& display_path,
                           const std::filesystem::path& base_dir);

// Reads and parses a scene file; paths inside it resolve against its folder.
SceneDesc load_scene_file(const std::filesystem::path& path);

// The scene `glint render` renders when given no file.
SceneDesc default_scene();
const std::string& default_scene_text();

}  // namespace glint
