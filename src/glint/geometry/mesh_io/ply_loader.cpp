// Stanford PLY, ascii or binary (little or big endian). Read: the `vertex` element's x, y, z and
// optional nx, ny, nz; `face` elements' vertex_indices (or vertex_index) lists of any size, split into
// fans; `tristrips` elements' vertex_indices strips (−1 restarts a strip; the winding alternates, and
// the degenerate triangles that stitch strips are dropped). Other elements and properties are read past.
#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
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
    PlyParser(std::string path, std::string bytes) : path_(std::move(path)), bytes_(std::move(bytes)) {}

    MeshData parse() {
        parse_header();
        for (const PlyElement& element : elements_) {
            read_element(element);
        }
        if (mesh_.triangles.empty()) {
            fail_header(1, 1, "the PLY file has no faces or triangle strips");
        }
        if (!has_normals_) {
            mesh_.normals.clear();
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
    [[noreturn]] void fail_header(int line, int column, const std::string& message) const {
        throw SceneError(SourcePos{text_file(), line, column}, message);
    }
    // An error in the data: file:line:col for ascii, the byte offset for binary; both name the element.
    [[noreturn]] void fail_data(const std::string& message) const {
        const std::string where =
            current_element_ ? current_element_->name + " " + std::to_string(current_index_) : "";
        if (format_ == PlyFormat::Ascii) {
            throw SceneError(SourcePos{text_file(), token_line_, token_column_},
                             "in " + where + ": " + message);
        }
        throw SceneError(SourcePos{SourceFile::from_text(path_, ""), 0, 0},
                         "at byte " + std::to_string(token_offset_) + " (" + where + "): " + message);
    }

    // --- header -------------------------------------------------------------------------------------
    void parse_header() {
        std::size_t pos = 0;
        int line_number = 0;
        bool saw_format = false;
        while (true) {
            if (pos >= bytes_.size()) {
                data_start_ = bytes_.size();
                fail_header(std::max(line_number, 1), 1, "the PLY header has no 'end_header' line");
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
                long long count = -1;
                words >> element.name >> count;
                if (element.name.empty() || !words || count < 0) {
                    fail_header(line_number, 1, "expected 'element <name> <count>'");
                }
                element.count = static_cast<std::uint64_t>(count);
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
                }
                if (!parse_type(type, property.type)) {
                    fail_header(line_number, 1, "unknown property type '" + type + "'");
                }
                words >> property.name;
                if (property.name.empty()) {
                    fail_header(line_number, 1, "the property has no name");
                }
                elements_.back().properties.push_back(std::move(property));
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
                fail_header(1, 1, std::string("the vertex element has no '") + axis + "' property");
            }
        }
        cursor_ = data_start_;
        line_ = line_number + 1;
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
        token_column_ = static_cast<int>(cursor_ - line_begin_) + 1;
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
    template <class T>
    static T load(const unsigned char* raw) {
        T value;
        std::memcpy(&value, raw, sizeof(T));
        return value;
    }

    // Where a value was read, so that an error found later can point at it.
    struct ValuePos {
        int line = 0, column = 0;
        std::size_t offset = 0;
    };

    // Reads a list property's items into `items` (ints), checking the count.
    void read_list(const PlyProperty& property, std::vector<long long>& items) {
        items.clear();
        item_pos_.clear();
        const double count = read_value(property.count_type);
        if (count < 0) {
            fail_data("a list has a negative length");
        }
        if (count > 1e9) {
            fail_data("a list claims more than a billion items");
        }
        if (format_ != PlyFormat::Ascii && count * static_cast<double>(type_size(property.type)) >
                                               static_cast<double>(bytes_.size() - cursor_)) {
            fail_data("a list of " + std::to_string(static_cast<long long>(count)) +
                      " items runs past the end of the file");
        }
        for (long long i = 0; i < static_cast<long long>(count); ++i) {
            const double value = read_value(property.type);
            if (value != std::floor(value) || std::abs(value) > 1e18) {
                fail_data("a vertex index is not an integer in range");
            }
            items.push_back(static_cast<long long>(value));
            item_pos_.push_back({token_line_, token_column_, token_offset_});
        }
    }

    // Item k of the last list read, as a vertex index.
    std::uint32_t vertex_index(const std::vector<long long>& items, std::size_t k) {
        const long long index = items[k];
        if (index < 0 || static_cast<std::uint64_t>(index) >= vertex_count_) {
            token_line_ = item_pos_[k].line;
            token_column_ = item_pos_[k].column;
            token_offset_ = item_pos_[k].offset;
            fail_data("vertex index " + std::to_string(index) + " is out of range (there are " +
                      std::to_string(vertex_count_) + " vertices)");
        }
        return static_cast<std::uint32_t>(index);
    }

    void read_element(const PlyElement& element) {
        current_element_ = &element;
        const bool is_vertex = element.name == "vertex";
        const bool is_face = element.name == "face";
        const bool is_strips = element.name == "tristrips";
        int slot[6] = {-1, -1, -1, -1, -1, -1};  // property index of x, y, z, nx, ny, nz
        static const char* kSlotNames[6] = {"x", "y", "z", "nx", "ny", "nz"};
        if (is_vertex) {
            for (std::size_t p = 0; p < element.properties.size(); ++p) {
                for (int s = 0; s < 6; ++s) {
                    if (element.properties[p].name == kSlotNames[s] && !element.properties[p].is_list) {
                        slot[s] = static_cast<int>(p);
                    }
                }
            }
            has_normals_ = slot[3] >= 0 && slot[4] >= 0 && slot[5] >= 0;
            // Never trust a count in the header for an allocation bigger than the file could hold.
            mesh_.positions.reserve(std::min<std::uint64_t>(element.count, bytes_.size() / 3));
        }
        std::vector<long long> items;
        double values[6] = {0, 0, 0, 0, 0, 0};
        for (std::uint64_t i = 0; i < element.count; ++i) {
            current_index_ = i;
            for (std::size_t p = 0; p < element.properties.size(); ++p) {
                const PlyProperty& property = element.properties[p];
                if (property.is_list) {
                    read_list(property, items);
                    const bool indices = property.name == "vertex_indices" || property.name == "vertex_index";
                    if (indices && is_face) {
                        add_polygon(items);
                    } else if (indices && is_strips) {
                        add_strips(items);
                    }
                    continue;
                }
                const double value = read_value(property.type);
                for (int s = 0; s < 6; ++s) {
                    if (slot[s] == static_cast<int>(p)) {
                        values[s] = value;
                    }
                }
            }
            if (is_vertex) {
                const Vec3 position{values[0], values[1], values[2]};
                if (!is_finite(position)) {
                    fail_data("the vertex position is not finite");
                }
                mesh_.positions.push_back(position);
                if (has_normals_) {
                    mesh_.normals.push_back({values[3], values[4], values[5]});
                }
            }
        }
        current_element_ = nullptr;
    }

    void add_polygon(const std::vector<long long>& polygon) {
        if (polygon.size() < 3) {
            fail_data("a face needs at least three vertices");
        }
        const std::uint32_t first = vertex_index(polygon, 0);
        std::uint32_t previous = vertex_index(polygon, 1);
        for (std::size_t k = 2; k < polygon.size(); ++k) {
            const std::uint32_t current = vertex_index(polygon, k);
            mesh_.triangles.push_back({first, previous, current});
            previous = current;
        }
    }

    void add_strips(const std::vector<long long>& strip) {
        std::size_t begin = 0;
        while (begin < strip.size()) {
            std::size_t end = begin;
            while (end < strip.size() && strip[end] != -1) {
                ++end;
            }
            for (std::size_t k = begin; k + 2 < end; ++k) {
                std::uint32_t a = vertex_index(strip, k);
                std::uint32_t b = vertex_index(strip, k + 1);
                const std::uint32_t c = vertex_index(strip, k + 2);
                if ((k - begin) % 2 == 1) {
                    std::swap(a, b);  // every other triangle of a strip is wound the other way
                }
                if (a != b && b != c && a != c) {
                    mesh_.triangles.push_back({a, b, c});
                }
            }
            begin = end + 1;
        }
    }

    std::string path_;
    std::string bytes_;
    PlyFormat format_ = PlyFormat::Ascii;
    std::vector<PlyElement> elements_;
    std::uint64_t vertex_count_ = 0;
    std::size_t data_start_ = 0;
    mutable std::shared_ptr<const SourceFile> text_file_;

    std::size_t cursor_ = 0;  // next byte of data
    int line_ = 1;            // ascii: line of cursor_, and where that line begins
    std::size_t line_begin_ = 0;
    int token_line_ = 0, token_column_ = 0;  // ascii: where the last word began
    std::size_t token_offset_ = 0;           // binary: where the last value began
    const PlyElement* current_element_ = nullptr;
    std::uint64_t current_index_ = 0;

    std::vector<ValuePos> item_pos_;  // where each item of the last list was read

    bool has_normals_ = false;
    MeshData mesh_;
};

}  // namespace

MeshData load_ply(const std::filesystem::path& path) {
    return PlyParser(path.string(), mesh_io::read_file(path)).parse();
}

}  // namespace glint
