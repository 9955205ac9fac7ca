// A built scene: the world (what integrators see) and the view (how it is looked at and rendered). No
// YAML, no names to resolve, everything checked.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "glint/render/render.hpp"
#include "glint/render/view.hpp"
#include "glint/world/world.hpp"

namespace glint {

struct SceneDesc;

struct Scene {
    std::shared_ptr<const World> world;  // shared: a view edit in `glint serve` keeps the built world
    View view;
};

// What a later build may reuse of an earlier one: shapes (a mesh read from its file, its BVH) by the
// text of their description, and the accelerator over exactly those shapes. `glint serve` keeps one, so a
// material edit re-reads no mesh and rebuilds no BVH. Files are not watched: a mesh changed on disk is
// read again only by a new cache.
struct WorldCache {
    std::map<std::string, std::shared_ptr<const Shape>> shapes;  // by the shape's description as text
    struct BuiltAccelerator {
        std::string name;
        std::vector<const Shape*> shapes;
        std::shared_ptr<const Accelerator> accelerator;
    };
    BuiltAccelerator accelerator;
};

// Validates the whole description and builds the scene. Throws SceneError at the first mistake.
Scene build_scene(const SceneDesc& desc, WorldCache* cache = nullptr);

// The two halves alone, for callers that keep one of them (the preview). Each checks its own keys;
// build_scene also checks that the top level has no unknown key.
View build_view(const SceneDesc& desc);
std::shared_ptr<const World> build_world(const SceneDesc& desc, WorldCache* cache = nullptr);

// True when two descriptions build the same world: they differ at most in the view's keys (`camera`, and
// `render` but for its `accelerator`). Positions are not compared.
bool same_world(const SceneDesc& a, const SceneDesc& b);

// The scene rendered by the one render loop (render/render.hpp).
inline RenderStats render(const Scene& scene, Film& film, const RenderCallbacks& callbacks = {}) {
    return render(*scene.world, scene.view, film, callbacks);
}

}  // namespace glint
