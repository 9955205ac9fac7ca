// JSON pointer → position, from nlohmann's SAX events. The events carry no position, but the parser
// reads its input through an iterator, and this one counts the bytes read: when an event arrives, the
// parser has read its token (and, after a number, the one byte that ends it). So a value or key begins
// at the first byte after the previous event's end that is not whitespace or a ',' or ':' between
// tokens.
#include "glint/import/json_positions.hpp"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>

namespace glint {
namespace {

// Pointers deeper than this are kept at their ancestor of this depth: a glTF importer's deepest is
// /materials/M/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform (6).
constexpr std::size_t kMaxDepth = 8;

// The text, read byte by byte, telling `*read` how many bytes the parser has taken.
class CountingIterator {
  public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    CountingIterator(const char* begin, const char* at, std::size_t* read)
        : begin_(begin), at_(at), read_(read) {}
    reference operator*() const { return *at_; }
    CountingIterator& operator++() {
        ++at_;
        *read_ = static_cast<std::size_t>(at_ - begin_);
        return *this;
    }
    CountingIterator operator++(int) {
        CountingIterator before = *this;
        ++*this;
        return before;
    }
    bool operator==(const CountingIterator& other) const { return at_ == other.at_; }
    bool operator!=(const CountingIterator& other) const { return at_ != other.at_; }

  private:
    const char* begin_;
    const char* at_;
    std::size_t* read_;
};

using Json = nlohmann::json;

class PositionRecorder : public nlohmann::json_sax<Json> {
  public:
    PositionRecorder(std::string_view text, const std::size_t& read,
                     std::unordered_map<std::string, std::size_t>& offsets)
        : text_(text), read_(read), offsets_(offsets) {
        if (text.size() >= 3 && std::memcmp(text.data(), "\xEF\xBB\xBF", 3) == 0) {
            last_read_ = 3;  // a byte order mark, which the parser skips
        }
    }

    bool null() override { return scalar(); }
    bool boolean(bool) override { return scalar(); }
    bool number_integer(number_integer_t) override { return scalar(); }
    bool number_unsigned(number_unsigned_t) override { return scalar(); }
    bool number_float(number_float_t, const string_t&) override { return scalar(); }
    bool string(string_t&) override { return scalar(); }
    bool binary(binary_t&) override { return scalar(); }

    bool start_object(std::size_t) override { return open(false); }
    bool start_array(std::size_t) override { return open(true); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }

    bool key(string_t& name) override {
        pointer_.resize(frames_.back().pointer_length);
        pointer_ += '/';
        pointer_ += json_pointer_token(name);
        if (frames_.size() <= kMaxDepth) {
            offsets_.emplace(pointer_, token_start());
        }
        last_read_ = read_;
        return true;
    }

    bool parse_error(std::size_t position, const std::string&,
                     const nlohmann::detail::exception& error) override {
        // `position` counts the bytes read, the offending one included (one past the end at the end).
        error_offset_ = std::min(position > 0 ? position - 1 : 0, text_.size());
        error_ = error.what();
        return false;
    }

    std::size_t error_offset() const { return error_offset_; }
    const std::string& error() const { return error_; }

  private:
    struct Frame {
        bool array = false;
        std::size_t next_index = 0;      // in an array, the index of its next element
        std::size_t pointer_length = 0;  // the length of the container's own pointer
    };

    // A value begins: its pointer is the next index of the array it is in (a member's was set by its
    // key, and recorded there). Scalars in arrays below the top level are not recorded.
    void begin_value(bool container) {
        if (frames_.empty()) {
            pointer_.clear();
            offsets_.emplace(pointer_, token_start());
        } else if (Frame& frame = frames_.back(); frame.array) {
            pointer_.resize(frame.pointer_length);
            pointer_ += '/';
            pointer_ += std::to_string(frame.next_index++);
            if (frames_.size() <= kMaxDepth && (container || frames_.size() <= 2)) {
                offsets_.emplace(pointer_, token_start());
            }
        }
        last_read_ = read_;
    }

    bool scalar() {
        begin_value(false);
        return true;
    }

    bool open(bool array) {
        begin_value(true);
        frames_.push_back({array, 0, pointer_.size()});
        return true;
    }

    bool close() {
        frames_.pop_back();
        last_read_ = read_;
        return true;
    }

    std::size_t token_start() const {
        std::size_t at = std::min(last_read_, text_.size());
        while (at < text_.size() && std::strchr(" \t\r\n,:", text_[at]) != nullptr && text_[at] != '\0') {
            ++at;
        }
        return at;
    }

    std::string_view text_;
    const std::size_t& read_;
    std::size_t last_read_ = 0;
    std::unordered_map<std::string, std::size_t>& offsets_;
    std::vector<Frame> frames_;
    std::string pointer_;
    std::size_t error_offset_ = 0;
    std::string error_;
};

// nlohmann's reason without its prefix and its own position ("[json.exception.parse_error.101] parse
// error at line 1, column 4: "), which the diagnostic gives.
std::string parse_error_reason(const std::string& what) {
    std::string reason = what;
    if (const std::size_t bracket = reason.find("] ");
        reason.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) {
        reason.erase(0, bracket + 2);
    }
    if (reason.rfind("parse error at line", 0) == 0) {
        if (const std::size_t colon = reason.find(": "); colon != std::string::npos) {
            reason.erase(0, colon + 2);
        }
    }
    return reason;
}

}  // namespace

std::string json_pointer_token(std::string_view key) {
    std::string token;
    token.reserve(key.size());
    for (const char c : key) {
        if (c == '~') {
            token += "~0";
        } else if (c == '/') {
            token += "~1";
        } else {
            token += c;
        }
    }
    return token;
}

JsonPositions::JsonPositions(std::shared_ptr<const SourceFile> source, SourcePos whole_file)
    : whole_file_(std::move(whole_file)), source_(std::move(source)) {
    const std::string& text = source_->text;
    line_starts_.push_back(0);
    for (const char *at = text.data(), *end = text.data() + text.size();
         (at = static_cast<const char*>(std::memchr(at, '\n', static_cast<std::size_t>(end - at)))) !=
         nullptr;) {
        ++at;
        line_starts_.push_back(static_cast<std::size_t>(at - text.data()));
    }
    std::size_t read = 0;
    PositionRecorder recorder(text, read, offsets_);
    const CountingIterator first(text.data(), text.data(), &read);
    const CountingIterator last(text.data(), text.data() + text.size(), &read);
    if (!Json::sax_parse(first, last, &recorder)) {
        throw SceneError(position_of_offset(recorder.error_offset()),
                         "malformed JSON: " + parse_error_reason(recorder.error()));
    }
}

SourcePos JsonPositions::at(std::string_view pointer) const {
    std::string key(pointer);
    while (true) {
        if (const auto found = offsets_.find(key); found != offsets_.end()) {
            return position_of_offset(found->second);
        }
        const std::size_t slash = key.rfind('/');
        if (slash == std::string::npos) {
            return whole_file_;
        }
        key.resize(slash);
    }
}

SourcePos JsonPositions::position_of_offset(std::size_t offset) const {
    const auto line = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset) - 1;
    // A 2 GiB file on one line has columns up to 2^31, one more than an int holds.
    const std::size_t column = std::min<std::size_t>(offset - *line + 1, std::numeric_limits<int>::max());
    return {source_, source_->first_line + static_cast<int>(line - line_starts_.begin()),
            static_cast<int>(column)};
}

}  // namespace glint
