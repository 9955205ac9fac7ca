// The text of a pbrt-v4 scene as a sequence of statements: `Directive args… "type name" value…`.
// Only the syntax is read here (comments, quoted strings, `[ ]` lists, parameter lists, Include and
// Import); what the statements mean is pbrt_scene.cpp's. Anything malformed is a SceneError at its
// file:line:col. A scene is untrusted input, so every size is bounded before it is allocated (the
// limits below, docs/import-pbrt.md).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "glint/params/diagnostics.hpp"

namespace glint {

// One parameter: `"float radius" 2` or `"rgb reflectance" [0.8 0.2 0.1]`.
struct PbrtParam {
    std::string type;  // as written: float, integer, rgb, spectrum, texture, …
    std::string name;
    SourcePos pos;                     // of the quoted "type name"
    std::vector<double> numbers;       // numeric values (float, integer, point3, rgb, spectrum pairs, …)
    std::vector<std::string> strings;  // string, texture and named-spectrum values
    std::vector<bool> booleans;        // bool values
    mutable bool used = false;         // read by the importer (the rest is reported as not read)
};

// One directive with its arguments: the words and numbers before the parameter list, then the list.
struct PbrtStatement {
    std::string directive;  // "Shape", "LookAt", …; "ImportBegin"/"ImportEnd" bracket an Import's file
    SourcePos pos;
    std::vector<std::string> strings;  // quoted (or, for ActiveTransform, bare) word arguments
    std::vector<double> numbers;       // numeric arguments (LookAt's 9, Transform's 16, …)
    std::vector<PbrtParam> params;
};

struct PbrtLimits {
    std::size_t max_file_bytes = std::size_t{64} << 20;    // one file; glint's own scene files' limit
    std::size_t max_total_bytes = std::size_t{256} << 20;  // all files read, Includes counted each time
    int max_include_depth = 32;                            // Include/Import inside Include/Import …
    std::size_t max_files = 1024;                          // Includes in all (a file included twice …)
    std::size_t max_list_values = 1'000'000;               // values in one [ ] list: glint's scene limit
};

// Reads `path` and every file it includes, handing each statement to `statement` in file order.
// Include and Import name files relative to `search_dir` (pbrt-v4 resolves every file name against
// the folder of the scene it was given). `mentioned_at` positions errors about the file as a whole.
void parse_pbrt_file(const std::filesystem::path& path, const std::filesystem::path& search_dir,
                     const std::function<void(PbrtStatement&)>& statement, const PbrtLimits& limits = {},
                     const SourcePos& mentioned_at = {});

// The same for text already in memory (tests, the fuzz harness), shown in messages as `display_path`.
void parse_pbrt_text(const std::string& text, const std::string& display_path,
                     const std::filesystem::path& search_dir,
                     const std::function<void(PbrtStatement&)>& statement, const PbrtLimits& limits = {});

}  // namespace glint
