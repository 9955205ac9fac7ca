// Where the values of a JSON text begin, by JSON pointer (RFC 6901: "/materials/3/occlusionTexture"):
// the positions of the glTF importer's messages, since tinygltf, which parses glTF files, keeps none.
// The text is read a second time for this, by nlohmann::json's SAX parser (the parser tinygltf uses,
// so the two accept the same texts), with an iterator that tells how far the parser has read.
#pragma once

#include <cstddef>
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
    // costs no million entries.
    SourcePos at(std::string_view pointer) const;
    bool contains(std::string_view pointer) const { return offsets_.count(std::string(pointer)) > 0; }

  private:
    SourcePos position_of_offset(std::size_t offset) const;

    SourcePos whole_file_;
    std::shared_ptr<const SourceFile> source_;
    std::unordered_map<std::string, std::size_t> offsets_;  // pointer → byte offset in the text
    std::vector<std::size_t> line_starts_;                  // the offset of each line's first byte
};

// A reference token of a JSON pointer: `key` with '~' written "~0" and '/' written "~1".
std::string json_pointer_token(std::string_view key);

}  // namespace glint
