// A parsed scene value, independent of the file format: what the YAML/JSON loader produces and the
// builders read. Every node keeps its position, so that any later check can point at the source.
#pragma once

#include <string>
#include <vector>

#include "glint/params/diagnostics.hpp"

namespace glint {

struct Node {
    enum class Kind { Null, Scalar, Sequence, Map };

    Kind kind = Kind::Null;
    SourcePos pos;
    std::string scalar;             // Kind::Scalar: the text as written
    std::vector<Node> items;        // Kind::Sequence: the elements; Kind::Map: the values, in file order
    std::vector<std::string> keys;  // Kind::Map: keys[i] names items[i]
    std::vector<SourcePos> key_positions;

    bool is_map() const { return kind == Kind::Map; }
    bool is_sequence() const { return kind == Kind::Sequence; }
    bool is_scalar() const { return kind == Kind::Scalar; }

    // The value under `key` in a map, or nullptr.
    const Node* find(const std::string& key) const;
    // "a number", "a list", "a map", … for messages.
    std::string describe() const;
    // Removes `key` and its value from a map; false if it was not there.
    bool remove(const std::string& key);
};

// The map {type: word} standing for a plain word where a typed object is expected (the short form
// `integrator: path`), positioned at the word; any other node is returned as it is.
Node typed_object(const Node& node);

}  // namespace glint
