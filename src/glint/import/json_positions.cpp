// JSON pointer → position, from nlohmann's SAX events. The events carry no position, but the parser
// reads its input through an iterator, and this one counts the bytes read: when an event arrives, the
// parser has read its token (and, after a number, the one byte that ends it). So a value or key begins
// at the first byte after the previous event's end that is not whitespace or a ',' or ':' between
// tokens. Lines are counted as the events arrive, in the order of the text, so the text is scanned once
// whatever the number of values.
#include "glint/import/json_positions.hpp"

#include <algorithm>
#include <cstring>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

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

using Place = JsonPositions::Place;

void append_pointer_token(std::string& pointer, std::string_view key) {
    for (const char c : key) {
        if (c == '~') {
            pointer += "~0";
        } else if (c == '/') {
            pointer += "~1";
        } else {
            pointer += c;
        }
    }
}

// The place of an offset, counting the newlines from the last one asked (offsets come in increasing
// order; an earlier one is counted from the start).
class LineCounter {
  public:
    explicit LineCounter(std::string_view text) : text_(text) {}

    Place place(std::size_t offset) {
        if (offset < at_.offset) {
            at_ = {};
        }
        offset = std::min(offset, text_.size());
        while (const void* newline = std::memchr(text_.data() + at_.offset, '\n', offset - at_.offset)) {
            at_.offset = at_.line_start =
                static_cast<std::size_t>(static_cast<const char*>(newline) - text_.data()) + 1;
            ++at_.line;
        }
        at_.offset = offset;
        return at_;
    }

  private:
    std::string_view text_;
    Place at_;
};

class PositionRecorder : public nlohmann::json_sax<Json> {
  public:
    PositionRecorder(std::string_view text, const std::size_t& read,
                     std::vector<JsonPositions::KeyedPlace>& places)
        : text_(text), read_(read), places_(places), lines_(text) {
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
        append_pointer_token(pointer_, name);
        if (frames_.size() <= kMaxDepth) {
            places_.push_back({JsonPositions::key_of(pointer_), lines_.place(token_start())});
        }
        last_read_ = read_;
        return true;
    }

    bool parse_error(std::size_t position, const std::string&,
                     const nlohmann::detail::exception& error) override {
        // `position` counts the bytes read, the offending one included (one past the end at the end).
        error_place_ = lines_.place(position > 0 ? position - 1 : 0);
        error_ = error.what();
        return false;
    }

    const Place& error_place() const { return error_place_; }
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
            places_.push_back({JsonPositions::key_of(pointer_), lines_.place(token_start())});
        } else if (Frame& frame = frames_.back(); frame.array) {
            pointer_.resize(frame.pointer_length);
            pointer_ += '/';
            pointer_ += std::to_string(frame.next_index++);
            if (frames_.size() <= kMaxDepth && (container || frames_.size() <= 2)) {
                places_.push_back({JsonPositions::key_of(pointer_), lines_.place(token_start())});
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
    std::vector<JsonPositions::KeyedPlace>& places_;
    LineCounter lines_;
    std::vector<Frame> frames_;
    std::string pointer_;
    Place error_place_;
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
    append_pointer_token(token, key);
    return token;
}

JsonPositions::JsonPositions(std::shared_ptr<const SourceFile> source, SourcePos whole_file)
    : whole_file_(std::move(whole_file)), source_(std::move(source)) {
    const std::string& text = source_->text;
    std::size_t read = 0;
    PositionRecorder recorder(text, read, places_);
    const CountingIterator first(text.data(), text.data(), &read);
    const CountingIterator last(text.data(), text.data() + text.size(), &read);
    if (!Json::sax_parse(first, last, &recorder)) {
        throw SceneError(position_of(recorder.error_place()),
                         "malformed JSON: " + parse_error_reason(recorder.error()));
    }
    // By key; of a key given twice (JSON allows it), the first.
    std::stable_sort(places_.begin(), places_.end(),
                     [](const KeyedPlace& a, const KeyedPlace& b) { return a.key < b.key; });
    places_.shrink_to_fit();
}

const JsonPositions::Place* JsonPositions::find(std::string_view pointer) const {
    const std::uint64_t key = key_of(pointer);
    const auto found = std::lower_bound(places_.begin(), places_.end(), key,
                                        [](const KeyedPlace& a, std::uint64_t k) { return a.key < k; });
    return found != places_.end() && found->key == key ? &found->place : nullptr;
}

SourcePos JsonPositions::at(std::string_view pointer) const {
    std::string key(pointer);
    while (true) {
        if (const Place* place = find(key); place != nullptr) {
            return position_of(*place);
        }
        const std::size_t slash = key.rfind('/');
        if (slash == std::string::npos) {
            return whole_file_;
        }
        key.resize(slash);
    }
}

SourcePos JsonPositions::position_of(const Place& place) const {
    std::shared_ptr<const SourceFile>& line = lines_[place.line];
    if (!line) {
        const std::string_view text = source_->text;
        const std::size_t end = std::min(text.find('\n', place.line_start), text.size());
        line = place.line == 1 ? source_
                               : SourceFile::excerpt(source_->path, source_->first_line + place.line - 1,
                                                     text.substr(place.line_start, end - place.line_start));
    }
    // A 2 GiB file on one line has columns up to 2^31, one more than an int holds.
    const std::size_t column =
        std::min<std::size_t>(place.offset - place.line_start + 1, std::numeric_limits<int>::max());
    return {line, source_->first_line + place.line - 1, static_cast<int>(column)};
}

}  // namespace glint
