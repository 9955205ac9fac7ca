// Harnesses scene_yaml and scene_json: scene text through the same path as `glint render FILE` —
// parse_scene_text, build_scene (with the command line's overrides, here tiny ones), render. JSON is
// read by the YAML loader too; the two harnesses differ in their seeds, dictionary and file name.
//
// Findings: a crash, a leak, a hang, unbounded memory, or an exception other than SceneError (the CLI
// catches only SceneError: anything else ends `glint render` with "terminate called").
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.hpp"
#include "glint/scene/scene_desc.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const glint::SceneDesc desc =
            glint::parse_scene_text(text, GLINT_FUZZ_SCENE_NAME, glint::fuzz::assets_dir());
        glint::build_view(desc);  // the scene's own render block and camera, which the flags replace
        glint::Scene scene = glint::build_scene(desc, glint::fuzz::tiny_render());
        glint::fuzz::render_tiny(scene);
    } catch (const glint::SceneError& e) {
        glint::fuzz::check_scene_error(e);
    }
    return 0;
}
