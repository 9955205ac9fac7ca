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
