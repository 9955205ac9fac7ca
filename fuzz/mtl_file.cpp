// Harness mtl: an MTL material library through load_mtl, each material mapped to glint's by the OBJ
// importer (material_from_mtl), and the mapped material built by the scene builder on a sphere, as
// `glint render model.obj` would. Texture names resolve against fuzz/assets.
//
// Findings: a crash, a leak, a hang, unbounded memory, an exception other than SceneError, a warning
// without a position in a file, or a mapped material the builder refuses for anything but its texture:
// an image file that does not exist or cannot be read, or one whose values are no reflectance (an HDR
// map_Kd above 1) — the MTL may name any file, and the builder says so at the map_Kd statement.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.hpp"
#include "glint/import/obj_scene.hpp"
#include "glint/import/scene_tree.hpp"
#include "glint/scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const glint::fuzz::TemporaryInputFile input(".mtl", data, size);
    std::vector<glint::MtlMaterial> materials;
    try {
        materials = glint::load_mtl(input.path(), {});
    } catch (const glint::SceneError& e) {
        glint::fuzz::check_scene_error(e);
        return 0;
    }
    const std::filesystem::path assets = glint::fuzz::assets_dir();
    for (const glint::MtlMaterial& material : materials) {
        std::vector<glint::SceneWarning> warnings;
        glint::Node node = glint::material_from_mtl(material, assets, assets, warnings);
        for (const glint::SceneWarning& warning : warnings) {
            GLINT_FUZZ_CHECK(warning.pos.file != nullptr);
            (void)warning.to_string();
        }
        const glint::SourcePos pos = material.pos;
        glint::SceneDesc desc;
        desc.base_dir = assets;
        glint::Node sphere = glint::scene_tree::map({{"type", glint::scene_tree::text("sphere", pos)},
                                                     {"radius", glint::scene_tree::number(1, pos)},
                                                     {"material", std::move(node)}},
                                                    pos);
        desc.root = glint::scene_tree::map(
            {{"render", glint::scene_tree::map({{"width", glint::scene_tree::number(4, pos)},
                                                {"height", glint::scene_tree::number(4, pos)}},
                                               pos)},
             {"objects", glint::scene_tree::list({std::move(sphere)}, pos)}},
            pos);
        try {
            (void)glint::build_scene(desc);
        } catch (const glint::SceneError& e) {
            // Only a texture can be refused: the mapping writes values the materials accept.
            const std::string message = e.what();
            GLINT_FUZZ_CHECK(message.find("texture image") != std::string::npos ||
                             message.find("must lie in [0, 1]") != std::string::npos);
        }
    }
    return 0;
}
