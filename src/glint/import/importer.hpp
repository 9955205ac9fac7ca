// Scenes written for other tools: the importers that turn a pbrt-v4, glTF 2.0 or OBJ file into the
// same SceneDesc tree a glint YAML file parses to. Everything downstream — the builder, `--set`, the
// preview, the writer — then works on imported scenes unchanged, and `glint convert` is just
// import + write_scene_yaml: rendering the written YAML builds the very same tree, so the same bits.
//
// An importer gives every node it makes the position in the imported file it comes from, so a build
// error points there; what it approximates or leaves out becomes a SceneWarning, also positioned. A
// malformed file is a SceneError, as for glint's own files.
#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "glint/scene/scene_desc.hpp"

namespace glint {

struct ImportOptions {
    std::string camera;  // glTF: the camera to look through, by name ("": the first)
};

using ImportFunction = SceneDesc (*)(const std::filesystem::path& path, const ImportOptions& options);

struct ImporterEntry {
    const char* extension;  // lower case, with the dot: ".obj"
    const char* format;     // for messages and --help: "Wavefront OBJ with MTL materials"
    ImportFunction import;
};

// The one extension → importer table (importer_table.cpp).
std::span<const ImporterEntry> importers();
// "Wavefront OBJ with MTL materials (.obj), …", for help texts.
std::string importer_formats();

// Any scene file glint opens: an importer's format by its extension (case-insensitive), anything else
// as glint's own YAML or JSON (load_scene_file).
SceneDesc load_scene(const std::filesystem::path& path, const ImportOptions& options = {});

// The YAML of a loaded scene for a file written in `output_dir`: every relative file path in the tree
// (the values of `file` and `image` keys, which resolve against desc.base_dir) rewritten to resolve the same
// from `output_dir`, so the written scene renders the same wherever it is saved.
std::string scene_yaml_for(const SceneDesc& desc, const std::filesystem::path& output_dir);

// The same with every relative file path made absolute: for a scene saved where glint cannot know (the
// preview's Export scene, downloaded by a browser), which then renders the same from any folder on
// this machine.
std::string scene_yaml_with_absolute_paths(const SceneDesc& desc);

}  // namespace glint
