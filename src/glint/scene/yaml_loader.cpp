// The only file of glint that knows YAML exists: it turns yaml-cpp's tree into glint::Node.
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <sstream>

#include "glint/scene/scene_desc.hpp"

namespace glint {

namespace {

SourcePos position(const std::shared_ptr<const SourceFile>& file, const YAML::Mark& mark) {
    if (mark.is_null()) {
        return {file, 0, 0};
    }
    return {file, mark.line + 1, mark.column + 1};
}

Node convert(const YAML::Node& yaml, const std::shared_ptr<const SourceFile>& file) {
    Node node;
    node.pos = position(file, yaml.Mark());
    switch (yaml.Type()) {
        case YAML::NodeType::Undefined:
        case YAML::NodeType::Null:
            node.kind = Node::Kind::Null;
            break;
        case YAML::NodeType::Scalar:
            node.kind = Node::Kind::Scalar;
            node.scalar = yaml.Scalar();
            break;
        case YAML::NodeType::Sequence:
            node.kind = Node::Kind::Sequence;
            for (const YAML::Node& item : yaml) {
                node.items.push_back(convert(item, file));
            }
            break;
        case YAML::NodeType::Map:
            node.kind = Node::Kind::Map;
            for (const auto& entry : yaml) {
                const SourcePos key_pos = position(file, entry.first.Mark());
                if (!entry.first.IsScalar()) {
                    throw SceneError(key_pos, "a key must be a plain word");
                }
                const std::string key = entry.first.Scalar();
                if (node.find(key)) {
                    throw SceneError(key_pos, "duplicate key '" + key + "'");
                }
                node.keys.push_back(key);
                node.key_positions.push_back(key_pos);
                node.items.push_back(convert(entry.second, file));
            }
            break;
    }
    return node;
}

}  // namespace

SceneDesc parse_scene_text(const std::string& text, const std::string& display_path,
                           const std::filesystem::path& base_dir) {
    const auto file = SourceFile::from_text(display_path, text);
    YAML::Node yaml;
    try {
        yaml = YAML::Load(text);
    } catch (const YAML::Exception& e) {
        throw SceneError(position(file, e.mark), "syntax error: " + e.msg);
    }
    SceneDesc desc;
    desc.root = convert(yaml, file);
    desc.base_dir = base_dir;
    if (!desc.root.is_map()) {
        throw SceneError(desc.root.pos.line > 0 ? desc.root.pos : SourcePos{file, 1, 1},
                         "a scene must be a map with keys such as camera, objects and lights");
    }
    return desc;
}

SceneDesc load_scene_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in || std::filesystem::is_directory(path)) {
        throw SceneError({SourceFile::from_text(path.string(), ""), 0, 0},
                         "cannot read the scene file (does it exist?)");
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parse_scene_text(text.str(), path.string(), path.parent_path());
}

}  // namespace glint
