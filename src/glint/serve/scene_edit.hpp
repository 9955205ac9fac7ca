// The scene description as the browser sees it, and the edits it may make.
//
// The page of `glint serve` works on the SceneDesc's Node tree, never on built C++ objects: it reads
// the tree as JSON, and a change is a list of edits (a path of keys and a new value) applied to the
// tree, which is then built again. A parameter another part of glint adds to a material, camera or
// integrator is therefore editable without a change here.
//
// What an edit may do is limited:
//  - only the sections render, camera, background and materials are editable, and of the lists
//    objects and lights, the parameters of an object's inline material (objects.<i>.material.<key>) and
//    of a light (lights.<i>.<key>), their items named by position from 0 (a JSON number or its digits);
//    an edit never adds or removes an object or a light, so these positions are stable for the whole
//    session. Values are numbers, booleans, lists of numbers, or single words (names from the tables:
//    "jittered", "path"); never a whole new object. What a value may be is the scene builder's to say:
//    the edited tree is built by the same constructors as a scene file, so a material or light edit
//    meets the same checks, with the same messages (422 at the value's line of the edited YAML);
//  - the edited scene may not refer to any file the loaded scene does not already refer to (checked on
//    the whole edited tree, so no sequence of edits gets round it), so the page can never make glint
//    open, or tell whether there is, any other file;
//  - the values that set the cost of a frame stay within preview_limits (serve_limits.hpp).
//
// apply_edit_request() is the whole path from a request body to the scene to build, without sockets:
// the server and the fuzz harness both go through it.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "glint/params/node.hpp"
#include "glint/scene/scene_desc.hpp"

namespace glint {

// A bad edit request (400); the message says what was wrong and what is allowed.
struct EditError : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

// A request body longer than preview_limits::kMaxRequestBodyBytes (413).
struct RequestTooLargeError : EditError {
    using EditError::EditError;
};

// A value past one of the preview's limits (422). `key` is the path ("render.max_depth"), `value` what
// the scene asks for and `maximum` the largest the preview renders.
struct PreviewLimitError : EditError {
    PreviewLimitError(std::string key_path, double asked, std::int64_t largest, const std::string& message)
        : EditError(message), key(std::move(key_path)), value(asked), maximum(largest) {}
    std::string key;
    double value;
    std::int64_t maximum;
};

// An edit that would make the scene refer to a file the loaded scene does not (403). Its message is
// always kFileReferenceRefused, whatever the name and whether such a file exists.
struct FileReferenceError : EditError {
    FileReferenceError();
};
inline constexpr const char* kFileReferenceRefused =
    "an edit may not name a file: the preview reads only the files the loaded scene refers to (add a "
    "file to the scene file, then load it again)";

struct SceneEdit {
    // Keys from the top of the scene, e.g. {"materials", "glass", "ior"}; a list item by its position in
    // digits, e.g. {"lights", "0", "intensity"}.
    std::vector<std::string> path;
    std::optional<Node> value;  // nullopt: remove the key
};

// The tree as JSON: maps → objects (in file order), lists → arrays, scalars → numbers when they are
// numbers, booleans when true/false, strings otherwise; null → null.
nlohmann::ordered_json node_to_json(const Node& node);

// Parses a request body as JSON: at most kMaxRequestBodyBytes (else RequestTooLargeError), nested at
// most kMaxJsonDepth deep, well formed (else EditError). Allocates in proportion to the body only.
nlohmann::json parse_request_json(std::string_view body);

// Reads {"edits": [{"path": [...], "value": ...}, ...]} (or one {"path", "value"}); a path key is a word
// or a list position (a non-negative JSON integer). Throws EditError for a path outside what the page
// may edit (see the top of this file).
std::vector<SceneEdit> parse_edits(const nlohmann::json& request);

// Applies the edits in order to `root` (a map), creating maps along a path as needed (but no material,
// object or light: an edit names one that exists, and of an object only an inline material). Throws
// EditError.
// Checks nothing about files or limits: apply_edit_request() does.
void apply_edits(Node& root, const std::vector<SceneEdit>& edits);

// The keys whose value names a file glint reads: a mesh's and an image texture's `file`, an
// environment light's `image`. A constructor that reads a file under another key must be added here.
inline constexpr std::array<std::string_view, 2> kFileKeys = {"file", "image"};

// Every file a tree refers to: the values of kFileKeys anywhere in it (a value that is not a single
// scalar is kept as its JSON text, so that it is compared whole).
std::set<std::string> file_references(const Node& root);

// Throws FileReferenceError when `root` refers to a file not in `allowed`.
void check_file_references(const Node& root, const std::set<std::string>& allowed);

// The first value of `root` past preview_limits (kNumericLimits, kMaxPixels), or nullopt. Values that
// are not numbers are left to the scene builder, which reports them at their position.
struct LimitViolation {
    std::string key;   // "render.max_depth", or "render.width × render.height"
    const Node* node;  // where it is in `root` (for a position), or nullptr
    double value;
    std::int64_t maximum;
    std::string message;  // says the key, the value, the maximum, and what to use instead
};
std::optional<LimitViolation> find_limit_violation(const Node& root);

// An edited scene, ready to build.
struct EditedScene {
    SceneDesc desc;    // parsed back from `yaml`, so that a build error points at a line of it
    std::string yaml;  // the edited scene as text (what the page exports)
};

// The edit path of `glint serve`, whole and without sockets: parses `request_body`, applies its edits to
// a copy of `scene`, refuses a file reference not in `allowed_files` and a value past the preview
// limits, then writes the result as YAML and parses it back. Throws EditError (or one of its
// subclasses above) or SceneError; never reads a file. Does not build the scene (the caller does, and
// building reads the scene's own files).
EditedScene apply_edit_request(const SceneDesc& scene, std::string_view request_body,
                               const std::set<std::string>& allowed_files);
// The same with the files `scene` itself refers to as the allowed ones (the first edit of a loaded
// scene; what a fuzzer calls).
EditedScene apply_edit_request(const SceneDesc& scene, std::string_view request_body);
// The same from parsed edits.
EditedScene apply_checked_edits(const SceneDesc& scene, const std::vector<SceneEdit>& edits,
                                const std::set<std::string>& allowed_files);

// A JSON number as scene text: integers as integers, other numbers in the shortest form that reads
// back to the same double. Throws EditError for non-finite numbers.
std::string number_text(const nlohmann::json& number);

}  // namespace glint
