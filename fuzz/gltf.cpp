// Harness gltf: a glTF 2.0 file (text, or binary when it starts with "glTF") through the same path as
// `glint render model.gltf` — tinygltf's parser, the importer (node hierarchy, materials, cameras,
// lights), the mesh reader's accessor checks, build_scene with tiny overrides, render — and
// `glint convert`'s promise that the written YAML reads back as the same tree.
//
// Findings: a crash, a leak, a hang, unbounded memory, an exception other than SceneError, a warning
// without a line and column, or a converted scene that does not read back as itself.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "fuzz_support.hpp"
#include "glint/import/importer.hpp"
#include "glint/scene/scene_writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    const glint::fuzz::TemporaryInputFile input(binary ? ".glb" : ".gltf", data, size);
    try {
        const glint::SceneDesc desc = glint::load_scene(input.path());
        for (const glint::SceneWarning& warning : desc.warnings) {
            // At a line and column of the JSON (docs/importers.md, "Where glTF messages point").
            GLINT_FUZZ_CHECK(warning.pos.file != nullptr && warning.pos.line > 0);
        }
        const std::string yaml = glint::write_scene_yaml(desc.root);
        const glint::SceneDesc reread = glint::parse_scene_text(yaml, "converted.yaml", desc.base_dir);
        GLINT_FUZZ_CHECK(glint::write_scene_yaml(reread.root) == yaml);
        glint::Scene scene = glint::build_scene(desc, glint::fuzz::tiny_render());
        glint::fuzz::render_tiny(scene);
    } catch (const glint::SceneError& e) {
        glint::fuzz::check_scene_error(e);
    }
    return 0;
}
