// Wavefront MTL material libraries, as the OBJ importer reads them (obj_scene.cpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glint/core/color.hpp"
#include "glint/params/diagnostics.hpp"

namespace glint {

// One `newmtl` block: the statements glint maps, each with where it was written (an unset position
// means the statement is absent).
struct MtlMaterial {
    std::string name;
    SourcePos pos;  // the newmtl line
    template <typename T>
    struct Stated {
        T value{};
        SourcePos pos;
        bool given() const { return pos.file != nullptr; }
    };
    Stated<Rgb> kd, ks, ke, tf;
    Stated<double> ns, ni, d;  // d also from `Tr` (as 1 − Tr)
    Stated<int> illum;
    Stated<std::string> map_kd;  // the file name, options left out
    // Statements glint does not map (map_Ks, bump, Pr, …), each once, for warnings.
    std::vector<std::pair<std::string, SourcePos>> ignored;
};

// Reads an MTL file: every newmtl block. A malformed statement (a number that is not one, a colour
// given as a spectrum or XYZ) is a SceneError at it; unknown statements are kept in `ignored`.
// Files larger than `max_bytes` are refused (MTL files are small; 64 MiB by default).
std::vector<MtlMaterial> load_mtl(const std::filesystem::path& path, const SourcePos& mentioned_at,
                                  std::uint64_t max_bytes = std::uint64_t{64} << 20);

}  // namespace glint
