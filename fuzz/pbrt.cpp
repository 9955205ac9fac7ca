// Harness pbrt: a pbrt-v4 scene's text through the same path as `glint render scene.pbrt` — the pbrt
// importer (tokenizer, parser, graphics state, conversion), build_scene with tiny overrides, render —
// and through `glint convert`'s promise: the written YAML reads back as the same tree.
//
// Findings: a crash, a leak, a hang, unbounded memory, an exception other than SceneError, or a
// converted scene that does not read back as itself.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.hpp"
#include "glint/import/pbrt_scene.hpp"
#include "glint/scene/scene_writer.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const glint::SceneDesc desc = glint::import_pbrt_text(text, "fuzz.pbrt", glint::fuzz::assets_dir());
        const std::string yaml = glint::write_scene_yaml(desc.root);
        const glint::SceneDesc reread =
            glint::parse_scene_text(yaml, "converted.yaml", glint::fuzz::assets_dir());
        GLINT_FUZZ_CHECK(glint::write_scene_yaml(reread.root) == yaml);
        glint::build_view(desc);
        glint::Scene scene = glint::build_scene(desc, glint::fuzz::tiny_render());
        glint::fuzz::render_tiny(scene);
    } catch (const glint::SceneError& e) {
        glint::fuzz::check_scene_error(e);
    }
    return 0;
}
