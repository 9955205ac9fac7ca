#include "geometry/shape_testing.hpp"

#include "glint/params/diagnostics.hpp"
#include "glint/scene/scene.hpp"

namespace glint::testing {

std::string scene_error(const std::string& yaml) {
    try {
        const SceneDesc desc = parse_scene_text(yaml, "test.yaml", ".");
        build_scene(desc);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}

}  // namespace glint::testing
