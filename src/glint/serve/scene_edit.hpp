// The scene description as the browser sees it, and the edits it may make.
//
// The page of `glint serve` works on the SceneDesc's Node tree, never on built C++ objects: it reads
// the tree as JSON, and a change is a list of edits (a path of keys and a new value) applied to the
// tree, which is then built again. A parameter another part of glint adds to a material, camera or
// integrator is therefore editable without a change here.
//
// What an edit may do is limited so that the page cannot make glint read a file the scene does not
// reference: only the sections render, camera, background and materials are editable; values are
// numbers, booleans, lists of numbers, or single words (names from the tables: "jittered", "path");
// never a path, never a whole new object.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "glint/scene/node.hpp"

namespace glint {

// A bad edit request; the message says what was wrong and what is allowed.
struct EditError : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

struct SceneEdit {
    std::vector<std::string> path;  // keys from the top of the scene, e.g. {"materials", "glass", "ior"}
    std::optional<Node> value;      // nullopt: remove the key
};

// The tree as JSON: maps → objects (in file order), lists → arrays, scalars → numbers when they are
// numbers, booleans when true/false, strings otherwise; null → null.
nlohmann::ordered_json node_to_json(const Node& node);

// Reads {"edits": [{"path": [...], "value": ...}, ...]} (or one {"path", "value"}). Throws EditError.
std::vector<SceneEdit> parse_edits(const nlohmann::json& request);

// Applies the edits in order to `root` (a map), creating maps along a path as needed. Throws EditError.
void apply_edits(Node& root, const std::vector<SceneEdit>& edits);

// A JSON number as scene text: integers as integers, other numbers in the shortest form that reads
// back to the same double. Throws EditError for non-finite numbers.
std::string number_text(const nlohmann::json& number);

}  // namespace glint
