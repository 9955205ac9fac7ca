#pragma once

#include <filesystem>

namespace glint {

// What a constructor in a name → constructor table may need besides its own parameters.
struct BuildContext {
    std::filesystem::path base_dir;  // the scene file's folder: relative file names resolve here

    std::filesystem::path resolve(const std::filesystem::path& file) const {
        return file.is_absolute() ? file : base_dir / file;
    }
};

}  // namespace glint
