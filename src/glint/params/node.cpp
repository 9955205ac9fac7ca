#include "glint/params/node.hpp"

namespace glint {

const Node* Node::find(const std::string& key) const {
    for (size_t i = 0; i < keys.size(); ++i) {
        if (keys[i] == key) {
            return &items[i];
        }
    }
    return nullptr;
}

bool Node::remove(const std::string& key) {
    for (size_t i = 0; i < keys.size(); ++i) {
        if (keys[i] == key) {
            keys.erase(keys.begin() + static_cast<std::ptrdiff_t>(i));
            items.erase(items.begin() + static_cast<std::ptrdiff_t>(i));
            if (i < key_positions.size()) {
                key_positions.erase(key_positions.begin() + static_cast<std::ptrdiff_t>(i));
            }
            return true;
        }
    }
    return false;
}

Node typed_object(const Node& node) {
    if (!node.is_scalar()) {
        return node;
    }
    Node object;
    object.kind = Node::Kind::Map;
    object.pos = node.pos;
    object.keys.push_back("type");
    object.key_positions.push_back(node.pos);
    object.items.push_back(node);
    return object;
}

std::string Node::describe() const {
    switch (kind) {
        case Kind::Null:
            return "nothing";
        case Kind::Scalar:
            return "'" + scalar + "'";
        case Kind::Sequence:
            return "a list of " + std::to_string(items.size());
        case Kind::Map:
            return "a map";
    }
    return "?";
}

}  // namespace glint
