#include "glint/serve/scene_edit.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "glint/scene/scene_writer.hpp"
#include "glint/serve/serve_limits.hpp"
#include "glint/world/settings.hpp"

namespace glint {

namespace {

using preview_limits::kMaxEdits;
using preview_limits::kMaxListLength;
using preview_limits::kMaxPathLength;
using preview_limits::kMaxWordLength;

const std::array<const char*, 6> kEditableSections = {"render",    "camera",  "background",
                                                      "materials", "objects", "lights"};

// The position `key` names in a list of `size` items: its digits, below `size`; nullopt otherwise.
std::optional<size_t> list_index(const std::string& key, size_t size) {
    size_t index = 0;
    const auto [ptr, ec] = std::from_chars(key.data(), key.data() + key.size(), index);
    if (key.empty() || ec != std::errc() || ptr != key.data() + key.size() || index >= size) {
        return std::nullopt;
    }
    return index;
}

bool is_index(const std::string& key) {
    return list_index(key, std::numeric_limits<size_t>::max()).has_value();
}

// A scalar that is a whole number ("640", "-3") or a decimal number ("1.5", "1e-3"), as YAML writes it.
std::optional<nlohmann::ordered_json> scalar_number(const std::string& text) {
    if (text.empty() || text.size() > 64) {
        return std::nullopt;
    }
    const char* begin = text.data();
    const char* end = begin + text.size();
    if (*begin == '+') {
        ++begin;
    }
    std::int64_t integer = 0;
    auto [ptr, ec] = std::from_chars(begin, end, integer);
    if (ec == std::errc() && ptr == end) {
        return nlohmann::ordered_json(integer);
    }
    double value = 0;
    auto [dptr, dec] = std::from_chars(begin, end, value);
    if (dec == std::errc() && dptr == end && std::isfinite(value)) {
        return nlohmann::ordered_json(value);
    }
    return std::nullopt;
}

// At most kMaxWordLength bytes of `s` for a message, cut at a character boundary (the JSON reply must be
// valid UTF-8) and marked when cut.
std::string shown(const std::string& s, size_t max_bytes = kMaxWordLength) {
    if (s.size() <= max_bytes) {
        return s;
    }
    size_t end = max_bytes;
    while (end > 0 && (static_cast<unsigned char>(s[end]) & 0xC0) == 0x80) {
        --end;  // s[end] continues a multi-byte character: cut before that character
    }
    return s.substr(0, end) + "…";
}

bool is_word(const std::string& s) {
    if (s.empty() || s.size() > kMaxWordLength) {
        return false;
    }
    for (const char c : s) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                        c == '_' || c == '-';
        if (!ok) {
            return false;
        }
    }
    return true;
}

Node scalar_node(std::string text) {
    Node n;
    n.kind = Node::Kind::Scalar;
    n.scalar = std::move(text);
    return n;
}

std::string path_text(const std::vector<std::string>& path) {
    std::string out;
    for (const std::string& key : path) {
        if (!out.empty()) {
            out += '.';
        }
        out += key;
    }
    return out;
}

Node value_node(const nlohmann::json& value, const std::string& where) {
    if (value.is_number()) {
        return scalar_node(number_text(value));
    }
    if (value.is_boolean()) {
        return scalar_node(value.get<bool>() ? "true" : "false");
    }
    if (value.is_string()) {
        const auto& s = value.get_ref<const std::string&>();
        if (!is_word(s)) {
            throw EditError(where +
                            ": a text value must be one word of letters, digits, '_' or '-' (a name such as "
                            "'jittered'), not '" +
                            shown(s) + "'");
        }
        return scalar_node(s);
    }
    if (value.is_array()) {
        if (value.size() > kMaxListLength) {
            throw EditError(where + ": a list may hold at most " + std::to_string(kMaxListLength) +
                            " numbers");
        }
        Node list;
        list.kind = Node::Kind::Sequence;
        for (const auto& item : value) {
            if (!item.is_number()) {
                throw EditError(where + ": a list must hold numbers only");
            }
            list.items.push_back(scalar_node(number_text(item)));
        }
        return list;
    }
    throw EditError(where +
                    ": the value must be a number, true/false, a word, a list of numbers, or null to remove "
                    "the key");
}

}  // namespace

std::string number_text(const nlohmann::json& number) {
    if (number.is_number_integer()) {
        return number.dump();
    }
    const double value = number.get<double>();
    if (!std::isfinite(value)) {
        throw EditError("numbers must be finite");
    }
    if (value == std::trunc(value) && std::fabs(value) < 1e15) {
        return std::to_string(static_cast<std::int64_t>(value));
    }
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

nlohmann::ordered_json node_to_json(const Node& node) {
    switch (node.kind) {
        case Node::Kind::Null:
            return nullptr;
        case Node::Kind::Scalar: {
            if (auto number = scalar_number(node.scalar)) {
                return *number;
            }
            if (node.scalar == "true" || node.scalar == "false") {
                return node.scalar == "true";
            }
            return node.scalar;
        }
        case Node::Kind::Sequence: {
            auto array = nlohmann::ordered_json::array();
            for (const Node& item : node.items) {
                array.push_back(node_to_json(item));
            }
            return array;
        }
        case Node::Kind::Map: {
            auto object = nlohmann::ordered_json::object();
            for (size_t i = 0; i < node.items.size(); ++i) {
                object[node.keys[i]] = node_to_json(node.items[i]);
            }
            return object;
        }
    }
    return nullptr;
}

std::vector<SceneEdit> parse_edits(const nlohmann::json& request) {
    if (!request.is_object()) {
        throw EditError(
            "the request must be a JSON object: {\"edits\": [{\"path\": [...], \"value\": ...}]}");
    }
    std::vector<nlohmann::json> items;
    if (request.contains("edits")) {
        const auto& edits = request["edits"];
        if (!edits.is_array() || edits.empty()) {
            throw EditError("'edits' must be a non-empty list");
        }
        if (edits.size() > kMaxEdits) {
            throw EditError("at most " + std::to_string(kMaxEdits) + " edits per request");
        }
        items.assign(edits.begin(), edits.end());
    } else {
        items.push_back(request);
    }
    std::vector<SceneEdit> result;
    for (size_t i = 0; i < items.size(); ++i) {
        const auto& item = items[i];
        const std::string where = "edit " + std::to_string(i);
        if (!item.is_object() || !item.contains("path") || !item.contains("value")) {
            throw EditError(where + ": expected {\"path\": [keys...], \"value\": ...}");
        }
        const auto& path = item["path"];
        if (!path.is_array() || path.size() < 1 || path.size() > kMaxPathLength) {
            throw EditError(where + ": 'path' must be a list of 1 to " + std::to_string(kMaxPathLength) +
                            " keys");
        }
        SceneEdit edit;
        for (const auto& key : path) {
            // A list's item is named by its position: a number, or its digits as a word.
            if (key.is_number_unsigned()) {
                edit.path.push_back(std::to_string(key.get<std::uint64_t>()));
                continue;
            }
            if (!key.is_string() || !is_word(key.get<std::string>())) {
                throw EditError(where +
                                ": each key of 'path' must be a word (letters, digits, '_', '-') or the "
                                "position of a list item (0, 1, …)");
            }
            edit.path.push_back(key.get<std::string>());
        }
        bool editable = false;
        for (const char* section : kEditableSections) {
            editable = editable || edit.path[0] == section;
        }
        if (!editable) {
            throw EditError(
                where + ": '" + path_text(edit.path) +
                "' cannot be edited from the page (editable: render, camera, background, materials, "
                "an object's inline material, lights)");
        }
        if (edit.path[0] == "materials" && edit.path.size() < 3) {
            throw EditError(where + ": edit a material's parameter, e.g. materials.<name>.albedo");
        }
        // Of an object only its own material: its shape, place and transform stay as loaded (they are
        // the meshes and BVHs an edit never rebuilds), and no object is added or removed.
        if (edit.path[0] == "objects" &&
            (edit.path.size() < 4 || !is_index(edit.path[1]) || edit.path[2] != "material")) {
            throw EditError(where + ": '" + path_text(edit.path) +
                            "' cannot be edited from the page: of an object only the parameters of its "
                            "inline material can, objects.<index>.material.<parameter>, e.g. "
                            "objects.0.material.albedo");
        }
        // A light's parameters, but no light added or removed.
        if (edit.path[0] == "lights" && (edit.path.size() < 3 || !is_index(edit.path[1]))) {
            throw EditError(where + ": '" + path_text(edit.path) +
                            "' cannot be edited from the page: edit a light's parameter, "
                            "lights.<index>.<parameter>, e.g. lights.0.intensity");
        }
        if (!item["value"].is_null()) {
            edit.value = value_node(item["value"], where + " (" + path_text(edit.path) + ")");
        }
        result.push_back(std::move(edit));
    }
    return result;
}

namespace {

// The sections that are lists, whose items an edit names by position (objects.3, lights.0).
bool is_list_section(const std::string& section) {
    return section == "objects" || section == "lights";
}

std::string singular(const std::string& section) {
    return section == "objects" ? "object" : "light";
}

// The list `path[0]` (objects or lights) of `root`; a scene without it has none to edit.
Node& list_section(Node& root, const std::vector<std::string>& path) {
    Node* section = const_cast<Node*>(root.find(path[0]));
    if (!section || !section->is_sequence() || section->items.empty()) {
        throw EditError("'" + path_text(path) + "': the scene has no " + path[0]);
    }
    return *section;
}

// The item `path[1]` of the list `section` (objects or lights), which must exist: an edit never adds one.
Node& list_item(Node& section, const std::vector<std::string>& path) {
    const std::string what = singular(path[0]);
    const size_t count = section.items.size();
    const auto index = list_index(path[1], count);
    if (!index) {
        throw EditError("'" + path_text(path) + "': there is no " + what + " " + shown(path[1]) +
                        " in the scene; it has " + std::to_string(count) + " " +
                        (count == 1 ? what : path[0]) + ", numbered from 0");
    }
    Node& item = section.items[*index];
    if (!item.is_map()) {
        throw EditError("'" + path_text(path) + "': " + what + " " + path[1] + " is " + item.describe() +
                        ", not a map");
    }
    return item;
}

// An object's material may be edited from the page only where the object holds it (inline): a named one
// is edited under materials, and an object without one is the default grey matte, which has no keys.
void check_inline_material(const Node& object, const std::vector<std::string>& path) {
    const Node* material = object.find("material");
    // Appended piece by piece: GCC 12 warns wrongly (-Wrestrict) about "'" + a temporary here.
    std::string where = "'";
    where.append(path_text(path)).append("': object ").append(path[1]);
    if (!material) {
        throw EditError(where +
                        " has no material of its own (it is the default grey matte); give it one in the "
                        "scene file");
    }
    if (material->is_scalar()) {
        // The same keys under the named material: objects.1.material.albedo → materials.red.albedo.
        const std::vector<std::string> keys(path.begin() + 3, path.end());
        throw EditError(where + " uses the named material '" + shown(material->scalar) +
                        "': edit it as materials." + shown(material->scalar) + "." + path_text(keys));
    }
    if (!material->is_map()) {
        throw EditError(where + "'s material is " + material->describe() + ", not a map");
    }
}

}  // namespace

void apply_edits(Node& root, const std::vector<SceneEdit>& edits) {
    if (!root.is_map()) {
        throw EditError("the scene is not a map");
    }
    for (const SceneEdit& edit : edits) {
        Node* node = &root;
        for (size_t i = 0; i + 1 < edit.path.size(); ++i) {
            if (i < 2 && is_list_section(edit.path[0])) {
                node = i == 0 ? &list_section(*node, edit.path) : &list_item(*node, edit.path);
                if (i == 1 && edit.path[0] == "objects") {
                    check_inline_material(*node, edit.path);
                }
                continue;
            }
            Node* child = const_cast<Node*>(node->find(edit.path[i]));
            if (!child) {
                if (!edit.value) {
                    node = nullptr;  // removing a key under a missing map: nothing to do
                    break;
                }
                if (edit.path[0] == "materials" && i == 1) {
                    throw EditError("there is no material '" + edit.path[1] + "' in the scene");
                }
                node->keys.push_back(edit.path[i]);
                node->key_positions.emplace_back();
                Node map;
                map.kind = Node::Kind::Map;
                node->items.push_back(map);
                child = &node->items.back();
            }
            if (child->kind == Node::Kind::Null && edit.value) {
                child->kind = Node::Kind::Map;
            }
            if (!child->is_map()) {
                throw EditError("'" + path_text(edit.path) + "': '" + edit.path[i] + "' is " +
                                child->describe() + ", not a map");
            }
            node = child;
        }
        if (!node) {
            continue;
        }
        if (!node->is_map()) {  // a path that ends at a list (parse_edits refuses one)
            throw EditError("'" + path_text(edit.path) + "' names a list item, not a parameter");
        }
        const std::string& key = edit.path.back();
        if (!edit.value) {
            node->remove(key);
            continue;
        }
        size_t index = 0;
        while (index < node->keys.size() && node->keys[index] != key) {
            ++index;
        }
        if (index < node->keys.size()) {
            node->items[index] = *edit.value;
        } else {
            node->keys.push_back(key);
            node->key_positions.emplace_back();
            node->items.push_back(*edit.value);
        }
    }
}

FileReferenceError::FileReferenceError() : EditError(kFileReferenceRefused) {}

nlohmann::json parse_request_json(std::string_view body) {
    if (body.size() > preview_limits::kMaxRequestBodyBytes) {
        throw RequestTooLargeError("the request body has " + std::to_string(body.size()) +
                                   " bytes; at most " + std::to_string(preview_limits::kMaxRequestBodyBytes) +
                                   " are accepted");
    }
    // The parser itself keeps its nesting on the heap, but everything that walks the result (copies,
    // dump, comparisons) recurses: refuse deep nesting while parsing, before the value exists.
    const auto depth_check = [](int depth, nlohmann::json::parse_event_t event, nlohmann::json&) {
        if ((event == nlohmann::json::parse_event_t::object_start ||
             event == nlohmann::json::parse_event_t::array_start) &&
            depth >= preview_limits::kMaxJsonDepth) {
            throw EditError("the request is nested more than " +
                            std::to_string(preview_limits::kMaxJsonDepth) +
                            " levels deep; an edit request needs 4");
        }
        return true;
    };
    try {
        return nlohmann::json::parse(body.begin(), body.end(), depth_check);
    } catch (const nlohmann::json::exception& e) {
        // "[json.exception.parse_error.101] parse error at line 1, column 5: …": keep what follows the
        // tag, shortened (it may quote the input).
        const std::string what = e.what();
        const size_t tag_end = what.find("] ");
        throw EditError("the request body is not valid JSON: " +
                        shown(tag_end == std::string::npos ? what : what.substr(tag_end + 2), 200));
    }
}

namespace {

void collect_file_references(const Node& node, std::set<std::string>& out) {
    if (node.is_map()) {
        for (size_t i = 0; i < node.items.size(); ++i) {
            const Node& value = node.items[i];
            for (const std::string_view key : kFileKeys) {
                if (node.keys[i] == key) {
                    out.insert(value.is_scalar() ? value.scalar : node_to_json(value).dump());
                }
            }
            collect_file_references(value, out);
        }
    } else if (node.is_sequence()) {
        for (const Node& item : node.items) {
            collect_file_references(item, out);
        }
    }
}

// A scalar that reads as a finite number, as the scene builder reads numbers; nullopt otherwise.
std::optional<double> finite_number(const Node* node) {
    if (!node || !node->is_scalar() || node->scalar.empty()) {
        return std::nullopt;
    }
    const char* begin = node->scalar.data();
    const char* end = begin + node->scalar.size();
    if (*begin == '+') {
        ++begin;
    }
    double value = 0;
    const auto [ptr, ec] = std::from_chars(begin, end, value);
    if (ec != std::errc() || ptr != end || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

std::string number_for_message(double value) {
    return number_text(nlohmann::json(value));
}

}  // namespace

std::set<std::string> file_references(const Node& root) {
    std::set<std::string> references;
    collect_file_references(root, references);
    return references;
}

void check_file_references(const Node& root, const std::set<std::string>& allowed) {
    for (const std::string& reference : file_references(root)) {
        if (allowed.count(reference) == 0) {
            throw FileReferenceError();  // the same words for every name: nothing about the file leaks
        }
    }
}

std::optional<LimitViolation> find_limit_violation(const Node& root) {
    const Node* render = root.is_map() ? root.find("render") : nullptr;
    if (render && !render->is_map()) {
        render = nullptr;  // the builder says what is wrong with it
    }
    for (const preview_limits::NumericLimit& limit : preview_limits::kNumericLimits) {
        // The section's map, its dotted path walked from the top ("render.integrator").
        const Node* section = &root;
        for (size_t start = 0; section && start <= limit.section.size();) {
            const size_t dot = std::min(limit.section.find('.', start), limit.section.size());
            section = section->is_map() ? section->find(std::string(limit.section.substr(start, dot - start)))
                                        : nullptr;
            start = dot + 1;
        }
        const Node* node = section && section->is_map() ? section->find(std::string(limit.key)) : nullptr;
        const auto value = finite_number(node);
        if (value && *value > static_cast<double>(limit.maximum)) {
            const std::string key = std::string(limit.section) + "." + std::string(limit.key);
            return LimitViolation{key, node, *value, limit.maximum,
                                  key + " is " + number_for_message(*value) +
                                      "; the preview allows at most " + std::to_string(limit.maximum) +
                                      " (render beyond that with glint render)"};
        }
    }
    // Width and height are each within kMaxSide here; their product must fit kMaxPixels too.
    const RenderSettings defaults;
    const Node* width_node = render ? render->find("width") : nullptr;
    const Node* height_node = render ? render->find("height") : nullptr;
    const auto width = width_node ? finite_number(width_node) : std::optional<double>(defaults.width);
    const auto height = height_node ? finite_number(height_node) : std::optional<double>(defaults.height);
    if (width && height && *width > 0 && *height > 0 &&
        *width * *height > static_cast<double>(preview_limits::kMaxPixels)) {
        const double pixels = *width * *height;
        return LimitViolation{"render.width × render.height", width_node ? width_node : height_node, pixels,
                              preview_limits::kMaxPixels,
                              "render.width × render.height is " + number_for_message(*width) + " × " +
                                  number_for_message(*height) + " = " + number_for_message(pixels) +
                                  " pixels; the preview renders at most " +
                                  std::to_string(preview_limits::kMaxPixels) +
                                  " (2048 × 2048; render larger images with glint render)"};
    }
    return std::nullopt;
}

EditedScene apply_checked_edits(const SceneDesc& scene, const std::vector<SceneEdit>& edits,
                                const std::set<std::string>& allowed_files) {
    Node root = scene.root;
    apply_edits(root, edits);
    // Checked on the whole edited tree, not on the edits: whatever path and value an edit takes, the
    // scene that is built refers to no other file, and no value past a limit.
    check_file_references(root, allowed_files);
    if (const auto violation = find_limit_violation(root)) {
        throw PreviewLimitError(violation->key, violation->value, violation->maximum, violation->message);
    }
    EditedScene edited;
    edited.yaml = write_scene_yaml(root);
    edited.desc = parse_scene_text(edited.yaml, "<scene in the browser>", scene.base_dir);
    // What was parsed back is what gets built: check it again (a writer that changed a value would
    // otherwise slip past the checks above).
    check_file_references(edited.desc.root, allowed_files);
    if (const auto violation = find_limit_violation(edited.desc.root)) {
        throw PreviewLimitError(violation->key, violation->value, violation->maximum, violation->message);
    }
    return edited;
}

EditedScene apply_edit_request(const SceneDesc& scene, std::string_view request_body,
                               const std::set<std::string>& allowed_files) {
    return apply_checked_edits(scene, parse_edits(parse_request_json(request_body)), allowed_files);
}

EditedScene apply_edit_request(const SceneDesc& scene, std::string_view request_body) {
    return apply_edit_request(scene, request_body, file_references(scene.root));
}

}  // namespace glint
