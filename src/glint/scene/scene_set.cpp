#include "glint/scene/scene_set.hpp"

#include <charconv>
#include <sstream>
#include <vector>

namespace glint {

namespace {

// Moves every position of a value parsed from "v: <value>" onto the argument, where the value starts at
// column `value_column` (1-based).
void move_positions(Node& node, const std::shared_ptr<const SourceFile>& file, int value_column) {
    const auto move = [&](SourcePos& pos) {
        if (pos.line == 1) {
            pos.column += value_column - 4;  // "v: " is 3 columns
        }
        pos.file = file;
    };
    move(node.pos);
    for (SourcePos& pos : node.key_positions) {
        move(pos);
    }
    for (Node& item : node.items) {
        move_positions(item, file, value_column);
    }
}

// Keys whose plain word is the short form of {type: word}.
bool is_typed_short_form(const std::vector<std::string>& path, size_t depth) {
    return depth == 2 && path[0] == "render" &&
           (path[1] == "integrator" || path[1] == "sampler" || path[1] == "filter");
}

}  // namespace

void apply_set(SceneDesc& desc, const std::string& assignment, const std::string& source) {
    const auto file = SourceFile::from_text(source, assignment);
    const auto at = [&](size_t offset) { return SourcePos{file, 1, static_cast<int>(offset) + 1}; };
    const size_t equals = assignment.find('=');
    if (equals == std::string::npos) {
        throw SceneError(at(assignment.size()), "--set needs key.path=value, e.g. --set render.samples=64");
    }

    // The path, with the column of each key.
    std::vector<std::string> path;
    std::vector<size_t> columns;
    for (size_t start = 0;;) {
        const size_t dot = assignment.find('.', start);
        const size_t end = dot == std::string::npos || dot > equals ? equals : dot;
        if (end == start) {
            throw SceneError(at(start), "an empty key in --set " + assignment.substr(0, equals) +
                                            ": keys are separated by single dots");
        }
        path.push_back(assignment.substr(start, end - start));
        columns.push_back(start);
        if (end == equals) {
            break;
        }
        start = end + 1;
    }

    // The value, parsed as YAML and positioned in the argument.
    const std::string value_text = assignment.substr(equals + 1);
    SceneDesc parsed = parse_scene_text("v: " + value_text, source, desc.base_dir);
    Node value = parsed.root.items.empty() ? Node{} : parsed.root.items.front();
    move_positions(value, file, static_cast<int>(equals) + 2);
    if (value.kind == Node::Kind::Null) {
        value.pos = at(equals + 1);
    }

    Node* node = &desc.root;
    for (size_t depth = 0; depth < path.size(); ++depth) {
        const std::string& key = path[depth];
        const bool last = depth + 1 == path.size();
        if (is_typed_short_form(path, depth)) {
            *node = typed_object(*node);
        }
        if (node->kind == Node::Kind::Null) {
            node->kind = Node::Kind::Map;
        }
        if (node->is_sequence()) {
            size_t index = 0;
            const auto [end, error] = std::from_chars(key.data(), key.data() + key.size(), index);
            if (error != std::errc{} || end != key.data() + key.size() || index >= node->items.size()) {
                throw SceneError(at(columns[depth]), "'" + key + "' is not an element of this list of " +
                                                         std::to_string(node->items.size()) +
                                                         ": give its index, from 0");
            }
            node = &node->items[index];
        } else if (node->is_map()) {
            size_t index = 0;
            while (index < node->keys.size() && node->keys[index] != key) {
                ++index;
            }
            if (index == node->keys.size()) {
                node->keys.push_back(key);
                node->key_positions.push_back(at(columns[depth]));
                Node empty;
                empty.pos = at(columns[depth]);
                node->items.push_back(empty);
            }
            node = &node->items[index];
        } else {
            throw SceneError(at(columns[depth]), "cannot set '" + key + "' inside " + path[depth - 1] +
                                                     ", which is " + node->describe() + ", not a map");
        }
        if (last) {
            *node = value;
        }
    }
}

std::vector<std::pair<std::string, std::string>> flag_edits(const RenderFlags& flags, const SceneDesc& desc) {
    std::vector<std::pair<std::string, std::string>> edits;
    const auto add = [&](const char* flag, const std::string& key, const auto& value) {
        if (value) {
            std::ostringstream text;
            text.precision(17);  // a double as given, not rounded to 6 digits
            text << key << '=' << *value;
            edits.emplace_back(flag, text.str());
        }
    };
    add("--width", "render.width", flags.width);
    add("--height", "render.height", flags.height);
    add("--spp", "render.samples", flags.samples_per_pixel);
    add("--seed", "render.seed", flags.seed);
    add("--sampler", "render.sampler.type", flags.sampler);
    add("--integrator", "render.integrator.type", flags.integrator);
    add("--accel", "render.accelerator", flags.accelerator);
    add("--exposure", "render.exposure", flags.exposure);
    add("--tonemap", "render.tonemap", flags.tonemap);
    if (flags.crop) {
        edits.emplace_back("--crop", "render.crop=[" + *flags.crop + "]");
    }
    const Node* render = desc.root.find("render");
    const Node* integrator = render && render->is_map() ? render->find("integrator") : nullptr;
    const bool own_depth = integrator && integrator->is_map() && integrator->find("max_depth");
    add("--max-depth", own_depth ? "render.integrator.max_depth" : "render.max_depth", flags.max_depth);
    return edits;
}

void apply_flags(SceneDesc& desc, const RenderFlags& flags) {
    for (const auto& [flag, assignment] : flag_edits(flags, desc)) {
        apply_set(desc, assignment, flag);
    }
}

void apply_flags_and_sets(SceneDesc& desc, const RenderFlags& flags, std::span<const std::string> sets) {
    apply_flags(desc, flags);
    for (const std::string& set : sets) {
        apply_set(desc, set);
    }
}

Scene build_scene(SceneDesc desc, const RenderFlags& flags, std::span<const std::string> sets) {
    apply_flags_and_sets(desc, flags, sets);
    return build_scene(desc);
}

}  // namespace glint
