// The one extension → importer table. Adding a format: a file here and a line below.
#include <algorithm>
#include <cctype>

#include "glint/geometry/mesh_io/mesh_data.hpp"
#include "glint/import/gltf_scene.hpp"
#include "glint/import/importer.hpp"
#include "glint/import/obj_scene.hpp"
#include "glint/import/pbrt_scene.hpp"
#include "glint/import/scene_tree.hpp"
#include "glint/scene/scene_writer.hpp"

namespace glint {

std::span<const ImporterEntry> importers() {
    static const ImporterEntry table[] = {
        {".obj", "Wavefront OBJ with MTL materials", &import_obj_scene},
        {".gltf", "glTF 2.0", &import_gltf_scene},
        {".glb", "glTF 2.0 binary", &import_gltf_scene},
        {".pbrt", "pbrt-v4", &import_pbrt_scene},
    };
    return table;
}

std::string importer_formats() {
    std::string text;
    for (const ImporterEntry& entry : importers()) {
        text += (text.empty() ? "" : ", ") + std::string(entry.format) + " (" + entry.extension + ")";
    }
    return text;
}

SceneDesc load_scene(const std::filesystem::path& path, const ImportOptions& options) {
    const std::string extension = mesh_io::lower_case_extension(path);
    for (const ImporterEntry& entry : importers()) {
        if (extension == entry.extension) {
            return entry.import(path, options);
        }
    }
    return load_scene_file(path);
}

namespace {

// Rewrites the relative paths anywhere in the tree: the values of `file` (meshes, image textures) and of
// `image` when it is a file name (the environment light's map).
// Every relative `file` or `image` value of the tree, which resolves against `from`, replaced by
// `rewrite(from / value)`.
template <typename Rewrite>
void rebase_file_paths(Node& node, const std::filesystem::path& from, const Rewrite& rewrite) {
    if (node.is_map()) {
        for (std::size_t i = 0; i < node.items.size(); ++i) {
            Node& value = node.items[i];
            const bool path_key = node.keys[i] == "file" || node.keys[i] == "image";
            if (path_key && value.is_scalar() && std::filesystem::path(value.scalar).is_relative()) {
                value.scalar = rewrite(from / value.scalar);
            } else {
                rebase_file_paths(value, from, rewrite);
            }
        }
    } else if (node.is_sequence()) {
        for (Node& item : node.items) {
            rebase_file_paths(item, from, rewrite);
        }
    }
}

}  // namespace

std::string scene_yaml_for(const SceneDesc& desc, const std::filesystem::path& output_dir) {
    Node root = desc.root;
    const std::filesystem::path to = output_dir.empty() ? "." : output_dir;
    rebase_file_paths(
        root, desc.base_dir.empty() ? "." : desc.base_dir,
        [&](const std::filesystem::path& file) { return scene_tree::path_relative_to(file, to); });
    return write_scene_yaml(root);
}

std::string scene_yaml_with_absolute_paths(const SceneDesc& desc) {
    Node root = desc.root;
    rebase_file_paths(root, desc.base_dir.empty() ? "." : desc.base_dir,
                      [](const std::filesystem::path& file) {
                          return std::filesystem::absolute(file).lexically_normal().generic_string();
                      });
    return write_scene_yaml(root);
}

}  // namespace glint
