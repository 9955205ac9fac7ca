// The parsed, format-independent description of a scene: step one of scene file → SceneDesc → Scene.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "glint/params/diagnostics.hpp"
#include "glint/params/node.hpp"

namespace glint {

struct SceneDesc {
    Node root;                       // the top-level map: render, camera, materials, objects, lights, …
    std::filesystem::path base_dir;  // relative paths inside the scene resolve against this folder
    // What an importer approximated or left out (import/importer.hpp); glint's own files have none.
    std::vector<SceneWarning> warnings;
};

// Limits on a scene's text, checked before it is trusted (docs/scene-format.md, "Limits"):
// the size of a file; how deep lists and maps nest, counting nesting reached through aliases; how many
// values the scene expands to, counting an alias each time it is used (a hand-written scene has
// thousands; the cap keeps an alias bomb to about 0.2 GB and a fraction of a second); and how many bytes
// its scalars add up to, counted the same way (a long string repeated by a million aliases).
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t{64} << 20;
inline constexpr std::size_t kMaxSceneNesting = 100;
inline constexpr std::size_t kMaxSceneValues = 1'000'000;
inline constexpr std::size_t kMaxSceneValueBytes = std::size_t{256} << 20;

// Parses YAML (and so JSON) text. `display_path` names the file in error messages.
// Throws SceneError on a syntax error, a duplicate key, a top level that is not a map, a zero byte, a
// UTF-16/32 byte-order mark (libyaml would read UTF-16), bytes that are not UTF-8, or text beyond the
// limits above. Only the first YAML document of the text is read.
SceneDesc parse_scene_text(const std::string& text, const std::string& display_path,
                           const std::filesystem::path& base_dir);

// Reads and parses a scene file; paths inside it resolve against its folder.
SceneDesc load_scene_file(const std::filesystem::path& path);

// The scene `glint render` renders when given no file.
SceneDesc default_scene();
const std::string& default_scene_text();

}  // namespace glint
