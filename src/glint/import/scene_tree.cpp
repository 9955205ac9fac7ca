#include "glint/import/scene_tree.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>

#include "glint/core/math.hpp"

namespace glint::scene_tree {

std::string number_text(double value) {
    std::array<char, 32> buffer{};
    const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    (void)error;  // 32 characters hold any double
    return std::string(buffer.data(), end);
}

Node text(const std::string& value, const SourcePos& pos) {
    Node node;
    node.kind = Node::Kind::Scalar;
    node.scalar = value;
    node.pos = pos;
    return node;
}

Node number(double value, const SourcePos& pos) {
    return text(number_text(value), pos);
}

Node boolean(bool value, const SourcePos& pos) {
    return text(value ? "true" : "false", pos);
}

Node list(std::vector<Node> items, const SourcePos& pos) {
    Node node;
    node.kind = Node::Kind::Sequence;
    node.items = std::move(items);
    node.pos = pos;
    return node;
}

Node numbers(const std::vector<double>& values, const SourcePos& pos) {
    std::vector<Node> items;
    items.reserve(values.size());
    for (double value : values) {
        items.push_back(number(value, pos));
    }
    return list(std::move(items), pos);
}

Node vec3(const Vec3& value, const SourcePos& pos) {
    return numbers({value.x, value.y, value.z}, pos);
}

Node color(const Rgb& value, const SourcePos& pos) {
    return numbers({value.r, value.g, value.b}, pos);
}

Node map(std::vector<std::pair<std::string, Node>> entries, const SourcePos& pos) {
    Node node;
    node.kind = Node::Kind::Map;
    node.pos = pos;
    for (auto& [key, value] : entries) {
        node.keys.push_back(key);
        node.key_positions.push_back(value.pos);
        node.items.push_back(std::move(value));
    }
    return node;
}

void set(Node& map_node, const std::string& key, Node value) {
    for (std::size_t i = 0; i < map_node.keys.size(); ++i) {
        if (map_node.keys[i] == key) {
            map_node.items[i] = std::move(value);
            return;
        }
    }
    map_node.keys.push_back(key);
    map_node.key_positions.push_back(value.pos);
    map_node.items.push_back(std::move(value));
}

SourcePos file_position(const std::string& path) {
    return {SourceFile::from_text(path, ""), 0, 0};
}

Node framing_camera(const Bounds3& bounds, const SourcePos& pos) {
    constexpr double kFov = 40;
    const bool empty = bounds.lo.x > bounds.hi.x;
    const Vec3 centre = empty ? Vec3{0, 0, 0} : 0.5 * (bounds.lo + bounds.hi);
    const double radius = empty ? 1 : std::max(0.5 * length(bounds.hi - bounds.lo), 1e-6);
    const double distance = 1.1 * radius / std::sin(radians(kFov / 2));  // the sphere and a margin
    return map({{"type", text("pinhole", pos)},
                {"eye", vec3(centre + Vec3{0, 0, distance}, pos)},
                {"look_at", vec3(centre, pos)},
                {"fov", number(kFov, pos)}},
               pos);
}

Node white_sky(const SourcePos& pos) {
    return map({{"type", text("environment", pos)}, {"radiance", number(1, pos)}}, pos);
}

std::string path_relative_to(const std::filesystem::path& file, const std::filesystem::path& folder) {
    const std::filesystem::path absolute = std::filesystem::absolute(file).lexically_normal();
    const std::filesystem::path relative = absolute.lexically_relative(std::filesystem::absolute(folder));
    return (relative.empty() ? absolute : relative).generic_string();
}

}  // namespace glint::scene_tree
