// Where the values of a JSON text begin, by JSON pointer (RFC 6901: "/materials/3/occlusionTexture"):
// the positions of the glTF importer's messages, since tinygltf, which parses glTF files, keeps none.
// The text is read a second time for this, by nlohmann::json's SAX parser (the parser tinygltf uses,
// so the two accept the same texts), with an iterator that tells how far the parser has read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "glint/params/diagnostics.hpp"

namespace glint {

class JsonPositions {
  public:
    // Knows no value: every pointer is at `whole_file` (a position without a line).
    explicit JsonPositions(SourcePos whole_file) : whole_file_(std::move(whole_file)) {}

    // The positions of the values of `source->text`. A text that is not JSON is a SceneError at the
    // line and column where it stops being JSON, with nlohmann's reason.
    JsonPositions(std::shared_ptr<const SourceFile> source, SourcePos whole_file);

    // The position of the value at `pointer` (of its key, for a member of an object: the key is what
    // a reader looks for), or, when the text has no such value, of the nearest value that encloses it;
    // `whole_file` when there is none. Scalars inside arrays below the top level (a matrix's numbers,
    // a scene's node indices) are not kept, so they are at their array: a file of a million numbers
    // costs no million entries. The position's file is its line alone (lines cut out once each, and
    // the whole text for line 1), since quoting a line of a SourceFile reads the text up to it: a
    // thousand warnings deep in a large file would read it a thousand times. Not thread-safe.
    SourcePos at(std::string_view pointer) const;
    bool contains(std::string_view pointer) const { return find(pointer) != nullptr; }

    // Where a byte of the text is: its line, and the offset of that line's first byte.
    struct Place {
        std::size_t offset = 0;
        std::size_t line_start = 0;
        int line = 1;
    };

    // Places by a 64-bit hash of their pointer, in a sorted array: a large model has a million
    // values, and a hash map of strings made reading their positions cost three times nlohmann's own
    // parse. Two pointers of one file sharing a hash (odds about n² / 2^65) would misplace a message.
    struct KeyedPlace {
        std::uint64_t key = 0;
        Place place;
    };
    static std::uint64_t key_of(std::string_view pointer) { return std::hash<std::string_view>{}(pointer); }

  private:
    const Place* find(std::string_view pointer) const;
    SourcePos position_of(const Place& place) const;

    SourcePos whole_file_;
    std::shared_ptr<const SourceFile> source_;
    std::vector<KeyedPlace> places_;                                            // sorted by key
    mutable std::unordered_map<int, std::shared_ptr<const SourceFile>> lines_;  // cut out, by number
};

// A reference token of a JSON pointer: `key` with '~' written "~0" and '/' written "~1".
std::string json_pointer_token(std::string_view key);

}  // namespace glint
