// Harness scene_edit: the body of a POST /api/edit of `glint serve`, through what the server does with
// it (apply_edit_request in scene_edit.hpp: the JSON and its bounds, the edits, the rule that an edit
// names no new file, the preview's limits, the YAML written and parsed back), then built as the session
// builds it and rendered tiny. The loaded scene is fixed (below): one of every material, so that
// edits of their parameters reach every material's checks, an inline material and three lights, which
// edits reach by position (objects.<i>.material.<key>, lights.<i>.<key>).
//
// Findings: a crash, a leak, a hang, unbounded memory, an exception other than EditError and SceneError
// (the two the server turns into 400 and 422), or a written tree that does not read back as the same
// tree (the edit would silently change meaning, or a saved scene would not load).
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fuzz_support.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_writer.hpp"
#include "glint/serve/scene_edit.hpp"

namespace {

const char* const kLoadedScene = R"(# the scene the fuzzed edits apply to
render: {width: 64, height: 48, samples: 4, sampler: jittered, integrator: path, max_depth: 4, seed: 1}
camera: {type: pinhole, eye: [0, 1.6, 7], look_at: [0, 0.8, 0], up: [0, 1, 0], fov: 35}
background: [0.55, 0.7, 0.9]
materials:
  floor: {type: matte, albedo: {type: checker, even: 0.8, odd: 0.2}}
  shiny: {type: phong, diffuse: 0.5, specular: 0.2, exponent: 32}
  coat: {type: plastic, diffuse: [0.2, 0.4, 0.8], ior: 1.5}
  steel: {type: metal, reflectance: 0.9, roughness: 0.3}
  rtiow: {type: fuzzy-metal, albedo: 0.8, fuzz: 0.2}
  glass: {type: dielectric, ior: 1.5, absorption: [0.1, 0, 0]}
  lamp: {type: emissive, radiance: [4, 4, 3], scale: 1}
  chrome: {type: mirror, reflectance: 0.95}
objects:
  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: floor}
  - {type: sphere, center: [0, 1, 0], radius: 1, material: glass}
  - {type: sphere, center: [-2.2, 0.7, 0.6], radius: 0.7, material: steel}
  - {type: box, min: [1.5, 0, 0], max: [2.5, 1, 1], material: coat}
  - {type: disk, center: [0, 0.01, 2], radius: 0.5, material: shiny}
  - {type: cylinder, base: [-1, 0, 2], top: [-1, 1, 2], radius: 0.3, material: rtiow}
  - {type: torus, center: [1, 0.3, 2], minor_radius: 0.1, major_radius: 0.3, material: chrome}
  - {type: rectangle, corner: [-1, 3, -1], edge1: [2, 0, 0], edge2: [0, 0, 2], material: lamp}
  - {type: sphere, center: [1.5, 2, -1], radius: 0.4, material: {type: matte, albedo: {type: checker, even: 0.7, odd: 0.1}}}
lights:
  - {type: ambient, radiance: 0.12}
  - {type: point, position: [4, 6, 5], intensity: 90}
  - {type: spot, position: [0, 5, 0], look_at: [0, 0, 0], intensity: 40, angle: 30}
)";

const glint::SceneDesc& loaded_scene() {
    static const glint::SceneDesc desc =
        glint::parse_scene_text(kLoadedScene, "<fuzz loaded scene>", glint::fuzz::assets_dir());
    return desc;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const glint::SceneDesc& loaded = loaded_scene();
    try {
        // The server's whole path from a body to a scene, without sockets: JSON and its bounds, the
        // edits, the file-reference rule, the preview's limits, and the written YAML parsed back.
        const glint::EditedScene edited =
            glint::apply_edit_request(loaded, std::string_view(reinterpret_cast<const char*>(data), size));
        // What it hands over must read back as the same tree (else a saved scene would not load).
        GLINT_FUZZ_CHECK(glint::same_tree(
            glint::parse_scene_text(edited.yaml, "<scene in the browser>", loaded.base_dir).root,
            edited.desc.root));
        glint::build_scene(edited.desc);  // as the session builds it (it reads only the scene's files)
        glint::Scene scene = glint::build_scene(edited.desc, glint::fuzz::tiny_render());
        glint::fuzz::render_tiny(scene);
    } catch (const glint::EditError& e) {
        glint::fuzz::refused(e);
        GLINT_FUZZ_CHECK(*e.what() != '\0');
    } catch (const glint::SceneError& e) {
        glint::fuzz::check_scene_error(e);
    }
    return 0;
}
