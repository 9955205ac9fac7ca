// The only file of glint that knows YAML exists: it turns yaml-cpp's tree into glint::Node.
//
// A scene file is untrusted input, so everything here is bounded before it is trusted (the limits are
// in scene_desc.hpp and docs/scene-format.md): the file's size, its encoding (UTF-8 only), its nesting,
// and the number of values it expands to. YAML aliases make the last one necessary: an alias is the
// node it names, not a copy, so `&a [*a]` is a node that contains itself (converting it recursed until
// the stack overflowed) and a few lines of aliases of aliases stand for billions of nodes.
#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

#include "glint/scene/scene_desc.hpp"

namespace glint {

namespace {

SourcePos position(const std::shared_ptr<const SourceFile>& file, const YAML::Mark& mark) {
    if (mark.is_null()) {
        return {file, 0, 0};
    }
    return {file, mark.line + 1, mark.column + 1};
}

class Converter {
  public:
    explicit Converter(std::shared_ptr<const SourceFile> file) : file_(std::move(file)) {}

    Node convert(const YAML::Node& yaml) {
        Node node;
        node.pos = position(file_, yaml.Mark());
        if (++values_ > kMaxSceneValues) {
            throw SceneError(node.pos, "the scene expands to more than " + std::to_string(kMaxSceneValues) +
                                           " values (are aliases (*name) repeating large parts of it?)");
        }

        // Few values can still be many bytes: a long string repeated by a million aliases.
        if (yaml.IsScalar() && (bytes_ += yaml.Scalar().size()) > kMaxSceneValueBytes) {
            throw SceneError(node.pos, "the scene's values add up to more than " +
                                           std::to_string(kMaxSceneValueBytes) +
                                           " bytes (are aliases (*name) repeating a long text?)");
        }
        // An alias to an enclosing node would make the tree infinite. yaml-cpp's own parser limits
        // nesting in the text, but not the depth reached through aliases, so this guards both.
        for (const YAML::Node& ancestor : ancestors_) {
            if (ancestor.is(yaml)) {
                // yaml-cpp gives an alias the position of its anchor, so that is where this points.
                throw SceneError(node.pos,
                                 "this anchored value contains an alias of itself (the value would "
                                 "be infinite)");
            }
        }
        if (ancestors_.size() >= kMaxSceneNesting) {
            throw SceneError(node.pos, "the scene nests deeper than " + std::to_string(kMaxSceneNesting) +
                                           " levels of lists and maps");
        }
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
                ancestors_.push_back(yaml);
                for (const YAML::Node& item : yaml) {
                    node.items.push_back(convert(item));
                }
                ancestors_.pop_back();
                break;
            case YAML::NodeType::Map:
                node.kind = Node::Kind::Map;
                ancestors_.push_back(yaml);
                for (const auto& entry : yaml) {
                    const SourcePos key_pos = position(file_, entry.first.Mark());
                    if (!entry.first.IsScalar()) {
                        throw SceneError(key_pos, "a key must be a plain word");
                    }
                    const std::string key = entry.first.Scalar();
                    if ((bytes_ += key.size()) > kMaxSceneValueBytes) {
                        throw SceneError(key_pos, "the scene's keys and values add up to more than " +
                                                      std::to_string(kMaxSceneValueBytes) + " bytes");
                    }
                    if (node.find(key)) {
                        throw SceneError(key_pos, "duplicate key '" + key + "'");
                    }
                    node.keys.push_back(key);
                    node.key_positions.push_back(key_pos);
                    node.items.push_back(convert(entry.second));
                }
                ancestors_.pop_back();
                break;
        }
        return node;
    }

  private:
    std::shared_ptr<const SourceFile> file_;
    std::vector<YAML::Node> ancestors_;  // the maps and lists enclosing the node being converted
    std::size_t values_ = 0;
    std::size_t bytes_ = 0;  // of scalars, keys included, counted each time an alias repeats them
};

// yaml-cpp reads UTF-16 and UTF-32 (by their byte-order marks or zero bytes) as well as UTF-8, and then
// reports positions in characters that are not the bytes of our copy of the text. A scene is UTF-8:
// anything with a zero byte is refused here, where the message can say so.
void check_encoding(const std::string& text, const std::shared_ptr<const SourceFile>& file) {
    const auto starts_with = [&](std::initializer_list<unsigned char> bytes) {
        return text.size() >= bytes.size() &&
               std::equal(bytes.begin(), bytes.end(), text.begin(),
                          [](unsigned char a, char b) { return a == static_cast<unsigned char>(b); });
    };
    const char* encoding = nullptr;
    if (starts_with({0xFF, 0xFE, 0, 0}) || starts_with({0, 0, 0xFE, 0xFF})) {
        encoding = "UTF-32";
    } else if (starts_with({0xFF, 0xFE}) || starts_with({0xFE, 0xFF})) {
        encoding = "UTF-16";
    }
    const std::size_t zero = text.find('\0');
    if (encoding || zero != std::string::npos) {
        SourcePos pos{file, 0, 0};
        if (!encoding) {
            // Point at the zero byte: its line and column in the text as read.
            pos.line =
                1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(zero), '\n'));
            const std::size_t line_start = text.rfind('\n', zero);
            pos.column = static_cast<int>(zero - (line_start == std::string::npos ? 0 : line_start + 1)) + 1;
        }
        throw SceneError(pos, encoding ? std::string("the scene file is ") + encoding +
                                             " text; glint reads UTF-8 (save it as UTF-8)"
                                       : "a zero byte: a scene file is UTF-8 text (is this a binary or "
                                         "UTF-16 file?)");
    }
}

}  // namespace

SceneDesc parse_scene_text(const std::string& text, const std::string& display_path,
                           const std::filesystem::path& base_dir) {
    if (text.size() > kMaxSceneFileBytes) {
        throw SceneError({SourceFile::from_text(display_path, ""), 0, 0},
                         "the scene is " + std::to_string(text.size()) + " bytes, more than " +
                             std::to_string(kMaxSceneFileBytes) + " a scene may have");
    }
    const auto file = SourceFile::from_text(display_path, text);
    check_encoding(text, file);
    YAML::Node yaml;
    try {
        yaml = YAML::Load(text);
    } catch (const YAML::DeepRecursion& e) {
        throw SceneError(
            position(file, e.mark),
            "the scene nests deeper than " + std::to_string(kMaxSceneNesting) + " levels of lists and maps");
    } catch (const YAML::Exception& e) {
        throw SceneError(position(file, e.mark), "syntax error: " + e.msg);
    }
    SceneDesc desc;
    desc.root = Converter(file).convert(yaml);
    desc.base_dir = base_dir;
    if (!desc.root.is_map()) {
        throw SceneError(desc.root.pos.line > 0 ? desc.root.pos : SourcePos{file, 1, 1},
                         "a scene must be a map with keys such as camera, objects and lights");
    }
    return desc;
}

SceneDesc load_scene_file(const std::filesystem::path& path) {
    const auto unreadable = [&](const std::string& why) {
        return SceneError({SourceFile::from_text(path.string(), ""), 0, 0}, why);
    };
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        throw unreadable("cannot read the scene file: it does not exist");
    }
    // Only a regular file has a size to check before reading: a folder, a pipe or /dev/zero does not.
    if (!std::filesystem::is_regular_file(path, ec)) {
        throw unreadable("cannot read the scene file: it is not a regular file");
    }
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec || size > kMaxSceneFileBytes) {
        throw unreadable(ec ? "cannot read the scene file: " + ec.message()
                            : "the scene file is " + std::to_string(size) + " bytes, more than " +
                                  std::to_string(kMaxSceneFileBytes) + " (the largest scene glint reads)");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw unreadable("cannot read the scene file (permission denied?)");
    }
    std::ostringstream text;
    text << in.rdbuf();
    return parse_scene_text(text.str(), path.string(), path.parent_path());
}

}  // namespace glint
