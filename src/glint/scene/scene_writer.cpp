#include "glint/scene/scene_writer.hpp"

#include <cstdio>

namespace glint {

namespace {

// Lines longer than this are written as blocks rather than on one line.
constexpr size_t kMaxFlowWidth = 100;

bool plain_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '.' || c == '/' || c == '+' || c == '-';
}

// Whether YAML reads `text` back unchanged, as a string, when written without quotes: only "safe"
// characters, single spaces between words, no leading "- ", and not one of the words YAML reads as null.
bool can_be_plain(const std::string& text) {
    if (text.empty() || text == "~" || text == "null" || text == "Null" || text == "NULL") {
        return false;
    }
    if (text.front() == ' ' || text.back() == ' ' ||
        (text[0] == '-' && (text.size() == 1 || text[1] == ' '))) {
        return false;
    }
    if (text.rfind("---", 0) == 0 || text.rfind("...", 0) == 0) {
        return false;  // document markers
    }
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == ' ') {
            if (text[i + 1] == ' ' || text[i + 1] == '-' || text[i + 1] == '#') {
                return false;
            }
        } else if (!plain_char(c)) {
            return false;
        }
    }
    return true;
}

std::string quoted(const std::string& text) {
    std::string out = "\"";
    for (const char c : text) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\t':
                out += "\\t";
                break;
            case '\r':
                out += "\\r";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
                    char escape[8];
                    std::snprintf(escape, sizeof(escape), "\\x%02x", static_cast<unsigned char>(c));
                    out += escape;
                } else {
                    out += c;  // UTF-8 bytes pass through
                }
        }
    }
    out += '"';
    return out;
}

std::string scalar_text(const std::string& text) {
    return can_be_plain(text) ? text : quoted(text);
}

// A node written on one line, if it has no nested collections inside collections deeper than one level
// and is short enough; "" when it must be a block.
std::string flow(const Node& node, int depth = 0) {
    switch (node.kind) {
        case Node::Kind::Null:
            return "~";
        case Node::Kind::Scalar:
            return scalar_text(node.scalar);
        case Node::Kind::Sequence:
        case Node::Kind::Map: {
            if (depth > 1) {
                return "";
            }
            const bool map = node.is_map();
            std::string out = map ? "{" : "[";
            for (size_t i = 0; i < node.items.size(); ++i) {
                const std::string item = flow(node.items[i], depth + 1);
                if (item.empty()) {
                    return "";
                }
                if (i) {
                    out += ", ";
                }
                if (map) {
                    out += scalar_text(node.keys[i]);
                    out += ": ";
                }
                out += item;
                if (out.size() > kMaxFlowWidth) {
                    return "";
                }
            }
            out += map ? '}' : ']';
            return out;
        }
    }
    return "";
}

void write_block(const Node& node, int indent, std::string& out);

// Writes a value that follows "key:" or "- " on the same line, or on indented lines below.
// `top_level`: a section of the scene (render, camera, objects, …).
void write_value(const Node& node, int indent, std::string& out, bool after_dash, bool top_level = false) {
    const std::string one_line = flow(node);
    const bool collection = node.is_map() || node.is_sequence();
    // Top-level maps are blocks; a top-level list is one line only if it holds plain values ([r, g, b]).
    bool plain_items = true;
    for (const Node& item : node.items) {
        plain_items = plain_items && !item.is_map() && !item.is_sequence();
    }
    const bool as_block = top_level && (node.is_map() || !plain_items);
    if (!one_line.empty() && (!collection || !as_block || node.items.empty())) {
        out += ' ';
        out += one_line;
        out += '\n';
        return;
    }
    if (after_dash && node.is_map()) {
        // "- key: value" with the map's other keys aligned under the first.
        std::string block;
        write_block(node, indent, block);
        out += ' ';
        out.append(block, static_cast<size_t>(indent));
        return;
    }
    out += "\n";
    write_block(node, indent, out);
}

void write_block(const Node& node, int indent, std::string& out) {
    const std::string pad(static_cast<size_t>(indent), ' ');
    if (node.is_map()) {
        for (size_t i = 0; i < node.items.size(); ++i) {
            out += pad;
            out += scalar_text(node.keys[i]);
            out += ':';
            const Node& value = node.items[i];
            // Lists under a key are indented too, so the file reads as nested.
            write_value(value, indent + 2, out, false);
        }
    } else if (node.is_sequence()) {
        for (const Node& item : node.items) {
            out += pad;
            out += '-';
            write_value(item, indent + 2, out, true);
        }
    } else {
        out += pad;
        out += flow(node);
        out += '\n';
    }
}

}  // namespace

std::string write_scene_yaml(const Node& root) {
    std::string out;
    if (root.is_map() && root.items.empty()) {
        return "{}\n";
    }
    if (root.is_map() || root.is_sequence()) {
        if (root.is_map()) {
            // Top-level sections are separated by a blank line, like the hand-written examples.
            for (size_t i = 0; i < root.items.size(); ++i) {
                if (i) {
                    out += "\n";
                }
                out += scalar_text(root.keys[i]);
                out += ':';
                write_value(root.items[i], 2, out, false, true);
            }
        } else {
            write_block(root, 0, out);
        }
        return out;
    }
    return flow(root) + "\n";
}

bool same_tree(const Node& a, const Node& b) {
    if (a.kind != b.kind || a.scalar != b.scalar || a.keys != b.keys || a.items.size() != b.items.size()) {
        return false;
    }
    for (size_t i = 0; i < a.items.size(); ++i) {
        if (!same_tree(a.items[i], b.items[i])) {
            return false;
        }
    }
    return true;
}

}  // namespace glint
