#include "glint/serve/scene_edit.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace glint {

namespace {

constexpr size_t kMaxEdits = 64;
constexpr size_t kMaxPathLength = 8;
constexpr size_t kMaxListLength = 16;
constexpr size_t kMaxWordLength = 64;

const std::array<const char*, 4> kEditableSections = {"render", "camera", "background", "materials"};

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
                            s.substr(0, kMaxWordLength) + "'");
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
            if (!key.is_string() || !is_word(key.get<std::string>())) {
                throw EditError(where + ": each key of 'path' must be a word (letters, digits, '_', '-')");
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
                "' cannot be edited from the page (editable: render, camera, background, materials)");
        }
        if (edit.path[0] == "materials" && edit.path.size() < 3) {
            throw EditError(where + ": edit a material's parameter, e.g. materials.<name>.albedo");
        }
        if (!item["value"].is_null()) {
            edit.value = value_node(item["value"], where + " (" + path_text(edit.path) + ")");
        }
        result.push_back(std::move(edit));
    }
    return result;
}

void apply_edits(Node& root, const std::vector<SceneEdit>& edits) {
    if (!root.is_map()) {
        throw EditError("the scene is not a map");
    }
    for (const SceneEdit& edit : edits) {
        Node* node = &root;
        for (size_t i = 0; i + 1 < edit.path.size(); ++i) {
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
        const std::string& key = edit.path.back();
        size_t index = 0;
        while (index < node->keys.size() && node->keys[index] != key) {
            ++index;
        }
        if (!edit.value) {
            if (index < node->keys.size()) {
                node->keys.erase(node->keys.begin() + static_cast<std::ptrdiff_t>(index));
                node->items.erase(node->items.begin() + static_cast<std::ptrdiff_t>(index));
                if (index < node->key_positions.size()) {
                    node->key_positions.erase(node->key_positions.begin() +
                                              static_cast<std::ptrdiff_t>(index));
                }
            }
        } else if (index < node->keys.size()) {
            node->items[index] = *edit.value;
        } else {
            node->keys.push_back(key);
            node->key_positions.emplace_back();
            node->items.push_back(*edit.value);
        }
    }
}

}  // namespace glint
