// The only file of glint that knows YAML exists: it builds glint::Node from libyaml's events.
//
// A scene file is untrusted input, so everything here is bounded before it is trusted (the limits are
// in scene_desc.hpp and docs/scene-format.md): the file's size, its encoding (UTF-8 only), its nesting,
// and the number of values it expands to. YAML aliases make the last one necessary: an alias stands for
// the whole value it names, so a few lines of aliases of aliases stand for billions of values, and
// `&a [*a]` names a value that would contain itself.
//
// libyaml's event parser, not yaml-cpp's tree: yaml-cpp spent 200 M instructions (20 ms) reading the
// 120 kB of examples/rtiow-final.yaml, libyaml 24 M; building the Node tree from events also saves
// yaml-cpp's own tree in between.
#include <yaml.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string_view>
#include <vector>

#include "glint/scene/scene_desc.hpp"

namespace glint {

namespace {

// libyaml counts lines and columns in characters; glint's positions are bytes of the line (what the
// quoted line and its caret are made of). A text of ASCII alone needs no conversion; otherwise the
// character index is walked to its byte, forwards from the last one asked (events come in text order).
class ByteColumns {
  public:
    explicit ByteColumns(const std::string& text)
        : text_(text),
          ascii_(std::all_of(text.begin(), text.end(),
                             [](char c) { return static_cast<unsigned char>(c) < 0x80; })),
          first_byte_(text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0),  // libyaml skips a UTF-8 byte-order mark
          byte_(first_byte_) {}

    SourcePos position(const std::shared_ptr<const SourceFile>& file, const yaml_mark_t& mark) {
        std::size_t column = mark.column;
        if (!ascii_) {
            // The line's start is `column` characters back from the mark's byte (back, so that the
            // cursor only moves forwards). Line 1 starts at byte 0, before any byte-order mark. It is
            // found once a line: walking back from every mark cost 8.3 M instructions on RTIOW's final
            // scene, whose lines are 200 characters of about 20 events each.
            const std::size_t at = byte_of(mark.index);
            if (mark.line != line_) {
                std::size_t start = at;
                for (std::size_t c = 0; c < mark.column && start > 0; ++c) {
                    do {
                        --start;
                    } while (start > 0 && is_continuation(text_[start]));
                }
                line_ = mark.line;
                line_start_ = mark.line == 0 ? 0 : start;
            }
            column = at - line_start_;
        }
        return {file, static_cast<int>(mark.line) + 1, static_cast<int>(column) + 1};
    }

  private:
    static bool is_continuation(char byte) { return (static_cast<unsigned char>(byte) & 0xC0) == 0x80; }

    // The byte at which character `index` starts (a UTF-8 continuation byte, 10xxxxxx, starts none).
    std::size_t byte_of(std::size_t index) {
        if (index < char_) {
            char_ = 0;
            byte_ = first_byte_;
        }
        while (char_ < index && byte_ < text_.size()) {
            ++byte_;
            while (byte_ < text_.size() && is_continuation(text_[byte_])) {
                ++byte_;
            }
            ++char_;
        }
        return byte_;
    }

    const std::string& text_;
    bool ascii_;
    std::size_t first_byte_;
    std::size_t char_ = 0, byte_;  // character char_ starts at byte byte_
    // The line of the last mark and the byte it starts at (no line yet: libyaml's lines are 0-based).
    std::size_t line_ = std::numeric_limits<std::size_t>::max(), line_start_ = 0;
};

// The 1-based line and byte column of byte `offset` of the file's text (clamped to its end): for what
// is found by byte, not by libyaml's marks (a zero byte, bad UTF-8).
SourcePos position_of_byte(const std::shared_ptr<const SourceFile>& file, std::size_t offset) {
    const std::string& text = file->text;
    offset = std::min(offset, text.size());
    const std::size_t line_start = offset == 0 ? std::string::npos : text.rfind('\n', offset - 1);
    const std::size_t column = line_start == std::string::npos ? offset : offset - line_start - 1;
    return {file,
            1 + static_cast<int>(
                    std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n')),
            1 + static_cast<int>(column)};
}

// One libyaml event, deleted when it goes.
struct Event {
    yaml_event_t event{};
    ~Event() { yaml_event_delete(&event); }
};

// A value named by an anchor (&name), kept to stand in for its aliases (*name), with what it adds to the
// limits each time it is used.
struct Anchored {
    Node node;
    bool complete = false;  // false while the value is still being read: an alias now is inside it
    std::size_t values = 0;
    std::size_t bytes = 0;
    std::size_t height = 0;  // how many levels of lists and maps it nests below itself
};

// The limits' counts over the tree built so far, aliases counted each time they are used.
struct Counts {
    std::size_t values = 0;
    std::size_t bytes = 0;
};

class Builder {
  public:
    Builder(const std::string& text, std::shared_ptr<const SourceFile> file)
        : file_(std::move(file)), columns_(text) {
        yaml_parser_initialize(&parser_);
        yaml_parser_set_input_string(&parser_, reinterpret_cast<const unsigned char*>(text.data()),
                                     text.size());
    }
    ~Builder() { yaml_parser_delete(&parser_); }
    Builder(const Builder&) = delete;
    Builder& operator=(const Builder&) = delete;

    // The first document's value (Null for an empty text). Later documents are not read.
    Node document() {
        Event start;
        next(start);  // the stream's start
        Event event;
        next(event);
        if (event.event.type != YAML_DOCUMENT_START_EVENT) {
            return Node{};  // no document at all
        }
        Event first;
        next(first);
        std::size_t height = 0;
        return value(first, 0, height);
    }

  private:
    void next(Event& event) {
        if (!yaml_parser_parse(&parser_, &event.event)) {
            throw syntax_error();
        }
    }

    SceneError syntax_error() {
        if (parser_.error == YAML_MEMORY_ERROR) {
            return SceneError({file_, 0, 0}, "out of memory while reading the scene");
        }
        if (parser_.error == YAML_READER_ERROR) {  // bad UTF-8: its byte offset, not a mark
            return SceneError(position_of_byte(file_, parser_.problem_offset),
                              std::string("the scene is not UTF-8 text here (") +
                                  (parser_.problem ? parser_.problem : "unreadable") +
                                  "): a scene file is UTF-8");
        }
        std::string message =
            std::string("syntax error: ") + (parser_.problem ? parser_.problem : "unreadable");
        if (parser_.context) {
            message += std::string(" ") + parser_.context;
            if (parser_.context_mark.line != parser_.problem_mark.line) {
                message += " at line " + std::to_string(parser_.context_mark.line + 1);
            }
        }
        return SceneError(position(parser_.problem_mark), message);
    }

    SourcePos position(const yaml_mark_t& mark) { return columns_.position(file_, mark); }

    void count_values(const SourcePos& pos, std::size_t values) {
        if ((counts_.values += values) > kMaxSceneValues) {
            throw SceneError(pos, "the scene expands to more than " + std::to_string(kMaxSceneValues) +
                                      " values (are aliases (*name) repeating large parts of it?)");
        }
    }
    void count_bytes(const SourcePos& pos, std::size_t bytes, const char* what) {
        // Few values can still be many bytes: a long string repeated by a million aliases.
        if ((counts_.bytes += bytes) > kMaxSceneValueBytes) {
            throw SceneError(pos, std::string("the scene's ") + what + " add up to more than " +
                                      std::to_string(kMaxSceneValueBytes) +
                                      " bytes (are aliases (*name) repeating a long text?)");
        }
    }

    // A list or map `depth` levels down (an alias's value: its deepest part) must be fewer than
    // kMaxSceneNesting levels down.
    static void check_nesting(const SourcePos& pos, std::size_t depth, const std::string& through = "") {
        if (depth >= kMaxSceneNesting) {
            throw SceneError(pos, "the scene nests deeper than " + std::to_string(kMaxSceneNesting) +
                                      " levels of lists and maps" + through);
        }
    }

    // The value that begins with `event`, `depth` lists and maps down; `height` is set to how many
    // levels it nests below itself.
    Node value(Event& event, std::size_t depth, std::size_t& height) {
        const yaml_event_t& e = event.event;
        if (e.type == YAML_ALIAS_EVENT) {
            return alias(e, depth, height);
        }
        Node node;
        node.pos = position(e.start_mark);
        count_values(node.pos, 1);
        height = 0;
        const Counts before = counts_;
        const yaml_char_t* anchor = nullptr;
        switch (e.type) {
            case YAML_SCALAR_EVENT:
                anchor = e.data.scalar.anchor;
                read_scalar(e, node);
                count_bytes(node.pos, node.scalar.size(), "values");
                break;
            case YAML_SEQUENCE_START_EVENT:
            case YAML_MAPPING_START_EVENT: {
                check_nesting(node.pos, depth);
                const bool is_map = e.type == YAML_MAPPING_START_EVENT;
                anchor = is_map ? e.data.mapping_start.anchor : e.data.sequence_start.anchor;
                if (anchor) {
                    anchors_[reinterpret_cast<const char*>(anchor)] = Anchored{};  // open: not complete
                }
                node.kind = is_map ? Node::Kind::Map : Node::Kind::Sequence;
                if (is_map) {
                    read_map(node, depth, height);
                } else {
                    read_sequence(node, depth, height);
                }
                break;
            }
            default:  // the parser gives nothing else where a value is expected
                throw SceneError(node.pos, "syntax error: a value was expected here");
        }
        if (anchor) {
            anchors_[reinterpret_cast<const char*>(anchor)] = Anchored{
                node, true, counts_.values - before.values + 1, counts_.bytes - before.bytes, height};
        }
        return node;
    }

    // YAML's null, as yaml-cpp read it: an unquoted, untagged ~, null, Null, NULL or nothing at all.
    static void read_scalar(const yaml_event_t& e, Node& node) {
        const std::string_view text(reinterpret_cast<const char*>(e.data.scalar.value), e.data.scalar.length);
        if (e.data.scalar.style == YAML_PLAIN_SCALAR_STYLE && e.data.scalar.tag == nullptr &&
            (text.empty() || text == "~" || text == "null" || text == "Null" || text == "NULL")) {
            node.kind = Node::Kind::Null;
            return;
        }
        node.kind = Node::Kind::Scalar;
        node.scalar = std::string(text);
    }

    void read_sequence(Node& node, std::size_t depth, std::size_t& height) {
        while (true) {
            Event item;
            next(item);
            if (item.event.type == YAML_SEQUENCE_END_EVENT) {
                return;
            }
            append_item(node, item, depth, height);
        }
    }

    // The value beginning with `event` as the next item of `node` (a list or map `depth` levels down,
    // nesting `height` levels below itself so far).
    void append_item(Node& node, Event& event, std::size_t depth, std::size_t& height) {
        std::size_t item_height = 0;
        node.items.push_back(value(event, depth + 1, item_height));
        height = std::max(height, item_height + 1);
    }

    void read_map(Node& node, std::size_t depth, std::size_t& height) {
        while (true) {
            Event key;
            next(key);
            if (key.event.type == YAML_MAPPING_END_EVENT) {
                return;
            }
            const yaml_event_t& k = key.event;
            const SourcePos key_pos = position(k.start_mark);
            if (k.type != YAML_SCALAR_EVENT) {
                throw SceneError(key_pos, "a key must be a plain word");
            }
            Node key_node;
            read_scalar(k, key_node);
            if (key_node.kind != Node::Kind::Scalar) {
                throw SceneError(key_pos, "a key must be a plain word");
            }
            count_bytes(key_pos, key_node.scalar.size(), "keys and values");
            if (node.find(key_node.scalar)) {
                throw SceneError(key_pos, "duplicate key '" + key_node.scalar + "'");
            }
            if (k.data.scalar.anchor) {  // an anchored key: its aliases are keys or values elsewhere
                anchors_[reinterpret_cast<const char*>(k.data.scalar.anchor)] =
                    Anchored{key_node, true, 1, key_node.scalar.size(), 0};
            }
            node.keys.push_back(std::move(key_node.scalar));
            node.key_positions.push_back(key_pos);
            Event item;
            next(item);
            append_item(node, item, depth, height);
        }
    }

    // A copy of the anchored value, counted again against the limits as if written out here.
    Node alias(const yaml_event_t& e, std::size_t depth, std::size_t& height) {
        const SourcePos pos = position(e.start_mark);
        const std::string name = reinterpret_cast<const char*>(e.data.alias.anchor);
        const auto found = anchors_.find(name);
        if (found == anchors_.end()) {
            throw SceneError(pos, "unknown alias *" + name + ": no value before it is anchored &" + name);
        }
        const Anchored& anchored = found->second;
        if (!anchored.complete) {
            throw SceneError(pos, "*" + name + " is inside the value anchored &" + name +
                                      ": the value contains an alias of itself (it would be infinite)");
        }
        check_nesting(pos, depth + anchored.height, " (through the alias *" + name + ")");
        count_values(pos, anchored.values);
        count_bytes(pos, anchored.bytes, "values");
        height = anchored.height;
        return anchored.node;
    }

    yaml_parser_t parser_{};
    std::shared_ptr<const SourceFile> file_;
    ByteColumns columns_;
    std::map<std::string, Anchored> anchors_;
    Counts counts_;
};

// libyaml reads UTF-16 (by its byte-order mark) as well as UTF-8, and then reports positions in
// characters that are not the bytes of our copy of the text. A scene is UTF-8:
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
        // At the zero byte: its line and column in the text as read.
        const SourcePos pos = encoding ? SourcePos{file, 0, 0} : position_of_byte(file, zero);
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
    SceneDesc desc;
    desc.root = Builder(text, file).document();
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
