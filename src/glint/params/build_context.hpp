#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <utility>

namespace glint {

class Params;
class Shape;
class Material;

// What a constructor in a name → constructor table may need besides its own parameters.
struct BuildContext {
    std::filesystem::path base_dir;  // the scene file's folder: relative file names resolve here

    // Set by the scene builder for lights: builds the shape `shape` describes (its `type` and keys),
    // adds it to the scene's objects with `material`, and returns where both now live. {type: area}
    // lights use it so that cameras and reflections see the emitter.
    std::function<std::pair<const Shape*, const Material*>(Params& shape, std::unique_ptr<Material> material)>
        add_object;

    std::filesystem::path resolve(const std::filesystem::path& file) const {
        return file.is_absolute() ? file : base_dir / file;
    }
};

}  // namespace glint
