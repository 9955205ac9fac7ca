// Stanford PLY, ascii or binary (little or big endian). Read: the `vertex` element's x, y, z,
// optional nx, ny, nz and optional texture coordinates (u, v; s, t; texture_u, texture_v); `face` elements'
// vertex_indices (or vertex_index) lists of any size, split into fans; `tristrips` elements' vertex_indices
// strips (−1 restarts a strip; the winding alternates, and the degenerate triangles that stitch strips are
// dropped). Other elements and properties are read past.
//
// Hostile files: every element's count is checked against MeshLimits and against what the bytes after
// the header can hold before anything is read or allocated, and so is every list's length before its
// items are read; index lists are turned into triangles as they are read, never stored; element names
// must differ (two `vertex` elements would give positions and normals of different lengths).
#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "glint/geometry/mesh_io/mesh_data.hpp"

namespace glint {
namespace {

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };
enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::Float32;  // of the value, or of each item of a list
    bool is_list = false;
    PlyType count_type = PlyType::UInt8;
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
    std::uint64_t header_line = 0;  // where the header declares it, for errors about its count
};

std::size_t type_size(PlyType type) {
    switch (type) {
        case PlyType::Int8:
        case PlyType::UInt8:
            return 1;
        case PlyType::Int16:
        case PlyType::UInt16:
            return 2;
        case PlyType::Int32:
        case PlyType::UInt32:
        case PlyType::Float32:
            return 4;
        case PlyType::Float64:
            return 8;
    }
    return 0;
}

bool parse_type(const std::string& word, PlyType& type) {
    static const std::pair<const char*, PlyType> kNames[] = {
        {"char", PlyType::Int8},       {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
        {"uint8", PlyType::UInt8},     {"short", PlyType::Int16},     {"int16", PlyType::Int16},
        {"ushort", PlyType::UInt16},   {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
        {"int32", PlyType::Int32},     {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
        {"float", PlyType::Float32},   {"float32", PlyType::Float32}, {"double", PlyType::Float64},
        {"float64", PlyType::Float64},
    };
    for (const auto& [name, t] : kNames) {
        if (word == name) {
            type = t;
            return true;
        }
    }
    return false;
}

class PlyParser {
  public:
    PlyParser(std::string path, std::string bytes, const MeshLimits& limits)
        : path_(std::move(path)), bytes_(std::move(bytes)), limits_(limits) {}

    MeshData parse() {
        parse_header();
        check_counts();
        for (const PlyElement& element : elements_) {
            read_element(element);
        }
        if (mesh_.triangles.empty()) {
            fail_header(1, 1, "the PLY file has no faces or triangle strips");
        }
        if (!has_normals_) {
            mesh_.normals.clear();
        }
        if (!has_uvs_) {
            mesh_.uvs.clear();
        }
        return std::move(mesh_);
    }

  private:
    // --- errors -------------------------------------------------------------------------------------
    std::shared_ptr<const SourceFile> text_file() const {
        if (!text_file_) {
            // Only text is quoted: the header, and for ascii files everything.
            text_file_ = SourceFile::from_text(
                path_, format_ == PlyFormat::Ascii ? bytes_ : bytes_.substr(0, data_start_));
        }
        return text_file_;
    }
    // Positions are ints; a file within the size limit could have more lines, or longer ones.
    static int clamp_to_int(std::uint64_t value) {
        return static_cast<int>(std::min<std::uint64_t>(value, std::numeric_limits<int>::max()));
    }
    [[noreturn]] void fail_header(std::uint64_t line, int column, const std::string& message) const {
        throw SceneError(SourcePos{text_file(), clamp_to_int(line), column}, message);
    }
    // An error in the data: file:line:col for ascii, the byte offset for binary; both name the element
    // and the record (for the vertex element: the vertex index).
    [[noreturn]] void fail_data(const std::string& message) const {
        const std::string where =
            current_element_ ? current_element_->name + " " + std::to_string(current_index_) : "";
        if (format_ == PlyFormat::Ascii) {
            throw SceneError(SourcePos{text_file(), clamp_to_int(token_line_), clamp_to_int(token_column_)},
                             "in " + where + ": " + message);
        }
        throw SceneError(SourcePos{SourceFile::from_text(path_, ""), 0, 0},
                         "at byte " + std::to_string(token_offset_) + " (" + where + "): " + message);
    }

    // --- header -------------------------------------------------------------------------------------
    void parse_header() {
        std::size_t pos = 0;
        std::uint64_t line_number = 0;
        bool saw_format = false;
        while (true) {
            if (pos >= bytes_.size()) {
                data_start_ = bytes_.size();
                fail_header(std::max<std::uint64_t>(line_number, 1), 1,
                            "the PLY header has no 'end_header' line");
            }
            std::size_t end = bytes_.find('\n', pos);
            if (end == std::string::npos) {
                end = bytes_.size();
            }
            std::string line = bytes_.substr(pos, end - pos);
            if (!line.empty() && line.back() == '\r') {
                line.pop_back();
            }
            ++line_number;
            pos = end + 1;
            data_start_ = std::min(pos, bytes_.size());
            std::istringstream words(line);
            std::string keyword;
            words >> keyword;
            if (line_number == 1) {
                if (keyword != "ply") {
                    fail_header(1, 1, "not a PLY file: the first line must be 'ply'");
                }
                continue;
            }
            if (keyword.empty() || keyword == "comment" || keyword == "obj_info") {
                continue;
            }
            if (keyword == "end_header") {
                break;
            }
            if (keyword == "format") {
                std::string format;
                words >> format;
                if (format == "ascii") {
                    format_ = PlyFormat::Ascii;
                } else if (format == "binary_little_endian") {
                    format_ = PlyFormat::BinaryLittleEndian;
                } else if (format == "binary_big_endian") {
                    format_ = PlyFormat::BinaryBigEndian;
                } else {
                    fail_header(line_number, 8,
                                "unknown PLY format '" + format +
                                    "' (expected ascii, binary_little_endian or binary_big_endian)");
                }
                saw_format = true;
            } else if (keyword == "element") {
                PlyElement element;
                element.header_line = line_number;
                std::string count;
                words >> element.name >> count;
                const auto [end_of_count, error] =
                    std::from_chars(count.data(), count.data() + count.size(), element.count);
                if (element.name.empty() || count.empty() || error != std::errc() ||
                    end_of_count != count.data() + count.size()) {
                    fail_header(line_number, 1,
                                "expected 'element <name> <count>' with a count of 0 to 2^64 - 1, found '" +
                                    line + "'");
                }
                expect_line_end(words, line_number);
                for (const PlyElement& earlier : elements_) {
                    if (earlier.name == element.name) {
                        fail_header(line_number, 1,
                                    "element '" + element.name + "' is declared twice (first on line " +
                                        std::to_string(earlier.header_line) +
                                        "): a PLY file's elements must have different names");
                    }
                }
                elements_.push_back(std::move(element));
            } else if (keyword == "property") {
                if (elements_.empty()) {
                    fail_header(line_number, 1, "a property before any element");
                }
                PlyProperty property;
                std::string type;
                words >> type;
                if (type == "list") {
                    property.is_list = true;
                    std::string count_type;
                    words >> count_type >> type;
                    if (!parse_type(count_type, property.count_type) ||
                        property.count_type == PlyType::Float32 || property.count_type == PlyType::Float64) {
                        fail_header(line_number, 1,
                                    "unknown or non-integer list count type '" + count_type + "'");
                    }
                    if (type == "list") {
                        fail_header(line_number, 1, "a list of lists is not a PLY property type");
                    }
                }
                if (!parse_type(type, property.type)) {
                    fail_header(line_number, 1,
                                "unknown property type '" + type +
                                    "' (expected char, uchar, short, ushort, int, uint, float, double, "
                                    "int8 to uint32, float32, float64 or list)");
                }
                words >> property.name;
                if (property.name.empty()) {
                    fail_header(line_number, 1, "the property has no name");
                }
                expect_line_end(words, line_number);
                PlyElement& element = elements_.back();
                for (const PlyProperty& earlier : element.properties) {
                    if (earlier.name == property.name) {
                        fail_header(line_number, 1,
                                    "element '" + element.name + "' has two properties named '" +
                                        property.name + "'");
                    }
                }
                element.properties.push_back(std::move(property));
            } else {
                fail_header(line_number, 1, "unknown PLY header line '" + keyword + "'");
            }
        }
        if (!saw_format) {
            fail_header(2, 1, "the PLY header has no 'format' line");
        }
        const auto vertex = std::find_if(elements_.begin(), elements_.end(),
                                         [](const PlyElement& e) { return e.name == "vertex"; });
        if (vertex == elements_.end()) {
            fail_header(1, 1, "the PLY file has no 'vertex' element");
        }
        vertex_count_ = vertex->count;
        for (const char* axis : {"x", "y", "z"}) {
            if (std::none_of(vertex->properties.begin(), vertex->properties.end(),
                             [&](const PlyProperty& p) { return p.name == axis && !p.is_list; })) {
                fail_header(
                    vertex->header_line, 1,
                    std::string("the vertex element has no '") + axis + "' property (or it is a list)");
            }
        }
        cursor_ = data_start_;
        line_ = line_number + 1;
    }

    void expect_line_end(std::istringstream& words, std::uint64_t line_number) const {
        std::string extra;
        if (words >> extra) {
            fail_header(line_number, 1, "unexpected '" + extra + "' at the end of the line");
        }
    }

    // Every element's count against the limits and against what the data after the header can hold,
    // before anything is read or allocated: a record takes at least one byte per scalar property and
    // one count per list in binary, and at least one word per property in ascii (a word and the blank
    // after it take two bytes, except the last word of the file).
    void check_counts() const {
        const std::uint64_t data_bytes = bytes_.size() - data_start_;
        std::uint64_t room = format_ == PlyFormat::Ascii ? (data_bytes + 1) / 2 : data_bytes;
        const char* unit = format_ == PlyFormat::Ascii ? " words" : " bytes";
        // The limits first: they hold whatever the file's size.
        for (const PlyElement& element : elements_) {
            if (element.name == "vertex" && element.count > limits_.max_vertices) {
                fail_header(element.header_line, 1,
                            "the PLY file declares " + std::to_string(element.count) +
                                " vertices, more than the limit of " +
                                mesh_io::limit_text(limits_.max_vertices));
            }
            if (element.name == "face" && element.count > limits_.max_triangles) {
                fail_header(element.header_line, 1,
                            "the PLY file declares " + std::to_string(element.count) +
                                " faces, more than the limit of " +
                                mesh_io::limit_text(limits_.max_triangles) +
                                " triangles (each face makes at least one)");
            }
        }
        for (const PlyElement& element : elements_) {
            std::uint64_t record = 0;  // the least a record of the element takes, in bytes or words
            for (const PlyProperty& property : element.properties) {
                record += format_ == PlyFormat::Ascii
                              ? 1
                              : type_size(property.is_list ? property.count_type : property.type);
            }
            if (element.count == 0) {
                continue;
            }
            if (record == 0) {
                fail_header(element.header_line, 1,
                            "element '" + element.name + "' has " + std::to_string(element.count) +
                                " records but no properties: its records would be empty");
            }
            if (element.count > room / record) {
                fail_header(element.header_line, 1,
                            "element '" + element.name + "' declares " + std::to_string(element.count) +
                                " records of at least " + std::to_string(record) + unit + ", but only " +
                                std::to_string(room) + unit +
                                " can follow in the file (after the elements before it)");
            }
            room -= element.count * record;
        }
    }

    // --- data ---------------------------------------------------------------------------------------
    // The next ascii word, remembering where it starts; "" at the end of the file.
    std::string_view next_word() {
        while (cursor_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[cursor_]))) {
            if (bytes_[cursor_] == '\n') {
                ++line_;
                line_begin_ = cursor_ + 1;
            }
            ++cursor_;
        }
        if (line_begin_ < data_start_) {
            line_begin_ = data_start_;
        }
        token_line_ = line_;
        token_column_ = cursor_ - line_begin_ + 1;
        const std::size_t begin = cursor_;
        while (cursor_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[cursor_]))) {
            ++cursor_;
        }
        return std::string_view(bytes_).substr(begin, cursor_ - begin);
    }

    double read_value(PlyType type) {
        if (format_ == PlyFormat::Ascii) {
            const std::string_view word = next_word();
            if (word.empty()) {
                fail_data("the file ends early");
            }
            double value = 0;
            const char* first = word.data() + (word[0] == '+' ? 1 : 0);
            const auto [end, error] = std::from_chars(first, word.data() + word.size(), value);
            if (error != std::errc() || end != word.data() + word.size()) {
                fail_data("expected a number, found '" + std::string(word) + "'");
            }
            if (type != PlyType::Float32 && type != PlyType::Float64 && value != std::floor(value)) {
                fail_data("expected an integer, found '" + std::string(word) + "'");
            }
            return value;
        }
        token_offset_ = cursor_;
        const std::size_t size = type_size(type);
        if (bytes_.size() - cursor_ < size) {
            fail_data("the file ends early");
        }
        unsigned char raw[8];
        std::memcpy(raw, bytes_.data() + cursor_, size);
        cursor_ += size;
        const bool file_is_little = format_ == PlyFormat::BinaryLittleEndian;
        if (file_is_little != (std::endian::native == std::endian::little)) {
            std::reverse(raw, raw + size);
        }
        switch (type) {
            case PlyType::Int8:
                return static_cast<double>(static_cast<std::int8_t>(raw[0]));
            case PlyType::UInt8:
                return static_cast<double>(raw[0]);
            case PlyType::Int16:
                return static_cast<double>(load<std::int16_t>(raw));
            case PlyType::UInt16:
                return static_cast<double>(load<std::uint16_t>(raw));
            case PlyType::Int32:
                return static_cast<double>(load<std::int32_t>(raw));
            case PlyType::UInt32:
                return static_cast<double>(load<std::uint32_t>(raw));
            case PlyType::Float32:
                return static_cast<double>(load<float>(raw));
            case PlyType::Float64:
                return load<double>(raw);
        }
        return 0;
    }
    // A value read from the file, as messages show it: an integer as one, anything else as the shortest
    // text that reads back as it.
    static std::string number_text(double value) {
        if (value == std::floor(value) && std::abs(value) < 0x1p63) {
            return std::to_string(static_cast<long long>(value));
        }
        char text[32];
        const auto result = std::to_chars(text, text + sizeof(text), value);
        return std::string(text, result.ptr);
    }

    template <class T>
    static T load(const unsigned char* raw) {
        T value;
        std::memcpy(&value, raw, sizeof(T));
        return value;
    }

    // A list's length, checked against what is left of the file (binary: bytes for its items; ascii:
    // words) before any item is read.
    std::uint64_t read_list_length(const PlyProperty& property) {
        const double count = read_value(property.count_type);  // an integer: read_value checked
        if (count < 0) {
            fail_data("a list has a negative length");
        }
        const std::uint64_t bytes_left = bytes_.size() - cursor_;
        const double room = format_ == PlyFormat::Ascii
                                ? static_cast<double>((bytes_left + 1) / 2)
                                : static_cast<double>(bytes_left / type_size(property.type));
        if (count > room) {
            // A float count may be beyond any integer (3.2e41): converting it would be undefined, so
            // such a count is printed as the number it is.
            std::ostringstream what;
            what << "a list of ";
            if (count < 0x1p63) {
                what << static_cast<std::uint64_t>(count);
            } else {
                what << count;
            }
            what << " items runs past the end of the file";
            fail_data(what.str());
        }
        return static_cast<std::uint64_t>(count);
    }

    // The next item of a vertex index list: a vertex index, or (`restart_allowed`, in strips) −1.
    std::int64_t read_vertex_index(const PlyProperty& property, bool restart_allowed) {
        const double value = read_value(property.type);
        if (restart_allowed && value == -1) {
            return -1;
        }
        if (!(value >= 0 && value < static_cast<double>(vertex_count_) && value == std::floor(value))) {
            fail_data("vertex index " + number_text(value) + " is out of range (there are " +
                      std::to_string(vertex_count_) + " vertices)");
        }
        return static_cast<std::int64_t>(value);
    }

    void add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (mesh_.triangles.size() >= limits_.max_triangles) {
            fail_data(
                "the PLY file makes more than " + mesh_io::limit_text(limits_.max_triangles) +
                " triangles (the limit: larger meshes do not fit the 32-bit indices and memory of glint)");
        }
        mesh_.triangles.push_back({a, b, c});
    }

    // A face's vertex list, split into a fan as it is read.
    void read_polygon(const PlyProperty& property) {
        const std::uint64_t count = read_list_length(property);
        if (count < 3) {
            fail_data("a face needs at least three vertices, this one has " + std::to_string(count));
        }
        const auto first = static_cast<std::uint32_t>(read_vertex_index(property, false));
        auto previous = static_cast<std::uint32_t>(read_vertex_index(property, false));
        for (std::uint64_t k = 2; k < count; ++k) {
            const auto current = static_cast<std::uint32_t>(read_vertex_index(property, false));
            add_triangle(first, previous, current);
            previous = current;
        }
    }

    // A tristrips list, into triangles as it is read: −1 restarts the strip; every other triangle of a
    // strip is wound the other way; the degenerate triangles that stitch strips together are dropped.
    void read_strips(const PlyProperty& property) {
        const std::uint64_t count = read_list_length(property);
        std::uint32_t before_last = 0, last = 0;
        std::uint64_t run = 0;  // vertices of the current strip so far
        for (std::uint64_t k = 0; k < count; ++k) {
            const std::int64_t item = read_vertex_index(property, true);
            if (item < 0) {
                run = 0;
                continue;
            }
            const auto current = static_cast<std::uint32_t>(item);
            if (run >= 2) {
                std::uint32_t a = before_last, b = last;
                if (run % 2 == 1) {
                    std::swap(a, b);
                }
                if (a != b && b != current && a != current) {
                    add_triangle(a, b, current);
                }
            }
            before_last = last;
            last = current;
            ++run;
        }
    }

    // Any other list: its items are read past.
    void skip_list(const PlyProperty& property) {
        const std::uint64_t count = read_list_length(property);
        for (std::uint64_t k = 0; k < count; ++k) {
            read_value(property.type);
        }
    }

    void read_element(const PlyElement& element) {
        current_element_ = &element;
        const bool is_vertex = element.name == "vertex";
        const bool is_face = element.name == "face";
        const bool is_strips = element.name == "tristrips";
        // Property index of x, y, z, nx, ny, nz and the texture coordinates u, v, which exporters
        // name u/v, s/t or texture_u/texture_v (pbrt's plymesh, Blender, meshlab).
        constexpr int kSlots = 8;
        int slot[kSlots] = {-1, -1, -1, -1, -1, -1, -1, -1};
        static const char* kSlotNames[kSlots] = {"x", "y", "z", "nx", "ny", "nz", "u", "v"};
        const auto slot_of = [](const std::string& name) {
            for (int s = 0; s < kSlots; ++s) {
                if (name == kSlotNames[s]) {
                    return s;
                }
            }
            if (name == "s" || name == "texture_u" || name == "texture_s") {
                return 6;
            }
            if (name == "t" || name == "texture_v" || name == "texture_t") {
                return 7;
            }
            return -1;
        };
        if (is_vertex) {
            for (std::size_t p = 0; p < element.properties.size(); ++p) {
                const int s = slot_of(element.properties[p].name);
                if (s >= 0 && !element.properties[p].is_list) {
                    slot[s] = static_cast<int>(p);
                }
            }
            // There is one vertex element (parse_header rejects a second), so the normals and texture
            // coordinates are all or none of the positions'.
            has_normals_ = slot[3] >= 0 && slot[4] >= 0 && slot[5] >= 0;
            has_uvs_ = slot[6] >= 0 && slot[7] >= 0;
            // check_counts has bounded the count by the file's size and the vertex limit.
            mesh_.positions.reserve(element.count);
            if (has_normals_) {
                mesh_.normals.reserve(element.count);
            }
            if (has_uvs_) {
                mesh_.uvs.reserve(element.count);
            }
        }
        double values[kSlots] = {0, 0, 0, 0, 0, 0, 0, 0};
        for (std::uint64_t i = 0; i < element.count; ++i) {
            current_index_ = i;
            for (std::size_t p = 0; p < element.properties.size(); ++p) {
                const PlyProperty& property = element.properties[p];
                if (property.is_list) {
                    const bool indices = property.name == "vertex_indices" || property.name == "vertex_index";
                    if (indices && is_face) {
                        read_polygon(property);
                    } else if (indices && is_strips) {
                        read_strips(property);
                    } else {
                        skip_list(property);
                    }
                    continue;
                }
                const double value = read_value(property.type);
                for (int s = 0; s < kSlots; ++s) {
                    if (slot[s] == static_cast<int>(p)) {
                        values[s] = value;
                        if (s < 3 && !(std::abs(value) <= kMaxMeshCoordinate)) {
                            fail_data(std::string("the vertex's ") + kSlotNames[s] + " coordinate " +
                                      number_text(value) +
                                      (std::isfinite(value) ? " is beyond float's range (at most 3.4e38 in "
                                                              "magnitude): the BVH could not bound it"
                                                            : " is not finite"));
                        }
                    }
                }
            }
            if (is_vertex) {
                mesh_.positions.push_back({values[0], values[1], values[2]});
                if (has_normals_) {
                    mesh_.normals.push_back({values[3], values[4], values[5]});
                }
                if (has_uvs_) {
                    mesh_.uvs.push_back({values[6], values[7]});
                }
            }
        }
        current_element_ = nullptr;
    }

    std::string path_;
    std::string bytes_;
    MeshLimits limits_;
    PlyFormat format_ = PlyFormat::Ascii;
    std::vector<PlyElement> elements_;
    std::uint64_t vertex_count_ = 0;
    std::size_t data_start_ = 0;
    mutable std::shared_ptr<const SourceFile> text_file_;

    std::size_t cursor_ = 0;  // next byte of data
    std::uint64_t line_ = 1;  // ascii: line of cursor_, and where that line begins
    std::size_t line_begin_ = 0;
    std::uint64_t token_line_ = 0, token_column_ = 0;  // ascii: where the last word began
    std::size_t token_offset_ = 0;                     // binary: where the last value began
    const PlyElement* current_element_ = nullptr;
    std::uint64_t current_index_ = 0;

    bool has_normals_ = false;
    bool has_uvs_ = false;
    MeshData mesh_;
};

}  // namespace

MeshData load_ply(const std::filesystem::path& path, const MeshLimits& limits,
                  const SourcePos& mentioned_at) {
    return PlyParser(path.string(), mesh_io::read_file(path, mentioned_at, limits.max_file_bytes), limits)
        .parse();
}

}  // namespace glint
