// Wavefront OBJ: `v x y z [w]`, `vn x y z`, `vt u [v [w]]` and `f` with v, v/vt, v//vn or v/vt/vn
// corners (1-based; negative indices count back from the latest vertex). Polygons of any size are split
// into a fan. `mtllib` and `usemtl` are recorded when the caller asks (ObjMaterialUse); groups and other
// statements are read past. Corners that share a position but not a normal or texture coordinate
// become separate vertices, so both can be interpolated per vertex.
//
// Hostile files: lines are read word by word, never split into a list first (a line of a billion
// corners costs only the triangles it makes); every count is checked against MeshLimits before it
// grows; coordinates must be finite and within float's range (kMaxMeshCoordinate).
#include <charconv>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "glint/core/hash.hpp"

#include "glint/geometry/mesh_io/mesh_data.hpp"

namespace glint {
namespace {

class ObjParser {
  public:
    ObjParser(std::string path, std::string text, const MeshLimits& limits, ObjMaterialUse* materials)
        : path_(std::move(path)), text_(std::move(text)), limits_(limits), materials_(materials) {}

    MeshData parse() {
        std::size_t start = 0;
        while (start <= text_.size()) {
            std::size_t end = text_.find('\n', start);
            if (end == std::string::npos) {
                end = text_.size();
            }
            ++line_number_;
            line_start_ = start;
            parse_line(std::string_view(text_).substr(start, end - start));
            start = end + 1;
        }
        if (mesh_.triangles.empty()) {
            fail(0, "the OBJ file has no faces");
        }
        if (!any_normal_) {
            mesh_.normals.clear();
        }
        if (!any_uv_) {
            mesh_.uvs.clear();
        }
        return std::move(mesh_);
    }

  private:
    // A word of the line and its column (0-based offset into the line).
    struct Token {
        std::string_view text;
        std::size_t column = 0;
    };

    // The words of a line, one at a time.
    class Words {
      public:
        explicit Words(std::string_view line) : line_(line) {}
        bool next(Token& token) {
            while (i_ < line_.size() && is_blank(line_[i_])) {
                ++i_;
            }
            const std::size_t begin = i_;
            while (i_ < line_.size() && !is_blank(line_[i_])) {
                ++i_;
            }
            token = {line_.substr(begin, i_ - begin), begin};
            return i_ > begin;
        }

      private:
        static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
        std::string_view line_;
        std::size_t i_ = 0;
    };

    SourcePos position(std::size_t column) const {
        // Positions are ints; a file within the size limit could have more lines or longer ones.
        constexpr std::uint64_t kIntMax = std::numeric_limits<int>::max();
        // Only the line is kept for the report: the file may be gigabytes.
        const std::size_t line_end = std::min(text_.find('\n', line_start_), text_.size());
        const int line = static_cast<int>(std::min<std::uint64_t>(line_number_, kIntMax));
        return {SourceFile::excerpt(path_, line,
                                    std::string_view(text_).substr(line_start_, line_end - line_start_)),
                line, static_cast<int>(std::min<std::uint64_t>(column + 1, kIntMax))};
    }
    SourcePos position(const Token& token) const {
        return position(static_cast<std::size_t>(token.text.data() - text_.data()) - line_start_);
    }
    [[noreturn]] void fail(std::size_t column, const std::string& message) const {
        throw SceneError(position(column), message);
    }
    [[noreturn]] void fail(const Token& token, const std::string& message) const {
        throw SceneError(position(token), message);
    }

    // Fails at `token` if a list already holding `size` items may not grow by one.
    void check_room(std::size_t size, std::uint64_t limit, const Token& token, const char* what) const {
        if (size >= limit) {
            fail(token, std::string("the OBJ file has more than ") + mesh_io::limit_text(limit) + " " + what +
                            " (the limit: larger meshes do not fit the 32-bit indices and memory of glint)");
        }
    }

    double number(const Token& token) const {
        double value = 0;
        const char* first = token.text.data();
        const char* last = first + token.text.size();
        if (first != last && *first == '+') {
            ++first;  // from_chars does not take a leading '+'
        }
        const auto [end, error] = std::from_chars(first, last, value);
        if (error == std::errc::result_out_of_range && end == last) {
            fail(token, "the number '" + std::string(token.text) + "' is out of range");
        }
        if (error != std::errc() || end != last) {
            fail(token, "expected a number, found '" + std::string(token.text) + "'");
        }
        if (!std::isfinite(value)) {
            fail(token, "the number '" + std::string(token.text) + "' is not finite");
        }
        return value;
    }

    // The three numbers after the keyword; `limit` bounds their magnitude.
    Vec3 vec3(Words& words, const Token& keyword, double limit, const char* what) const {
        double xyz[3];
        for (double& value : xyz) {
            Token token;
            if (!words.next(token)) {
                // (append, not "'" + std::string: GCC 12 warns wrongly about the latter, -Wrestrict)
                fail(keyword, std::string("'").append(keyword.text).append("' needs three numbers"));
            }
            value = number(token);
            if (std::abs(value) > limit) {
                fail(token, std::string("the ") + what + " coordinate " + std::string(token.text) +
                                " is beyond float's range (at most 3.4e38 in magnitude): the BVH could not "
                                "bound it");
            }
        }
        return {xyz[0], xyz[1], xyz[2]};
    }

    // A 1-based or negative index into a list of `count` items, as a 0-based index.
    std::uint32_t index(std::string_view text, const Token& token, std::size_t count, const char* what,
                        const char* plural) const {
        long long value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        const bool whole = end == text.data() + text.size();
        if (error == std::errc::result_out_of_range && whole) {
            fail(token, std::string(what) + " index " + std::string(text) + " is out of range (there are " +
                            std::to_string(count) + " " + plural + " so far)");
        }
        if (error != std::errc() || !whole) {
            fail(token, std::string("expected a ") + what + " index, found '" + std::string(text) + "'");
        }
        const long long n = static_cast<long long>(count);
        const long long resolved = value > 0 ? value - 1 : n + value;
        if (value == 0 || resolved < 0 || resolved >= n) {
            fail(token, std::string(what) + " index " + std::to_string(value) +
                            " is out of range (there are " + std::to_string(count) + " " + plural +
                            " so far)");
        }
        return static_cast<std::uint32_t>(resolved);
    }

    // A face corner's position, texture coordinate and normal indices (kNone where it has none).
    struct Corner {
        std::uint32_t v, vt, vn;
        bool operator==(const Corner&) const = default;
    };
    struct CornerHash {
        std::size_t operator()(const Corner& c) const {
            return static_cast<std::size_t>(hash_values(c.v, c.vt, c.vn));
        }
    };

    // The mesh vertex of a face corner "v", "v/vt", "v//vn" or "v/vt/vn".
    std::uint32_t corner(const Token& token) {
        const std::string_view text = token.text;
        const std::size_t slash1 = text.find('/');
        Corner c{index(text.substr(0, slash1), token, positions_.size(), "vertex", "vertices"), kNone, kNone};
        if (slash1 != std::string_view::npos) {
            const std::size_t slash2 = text.find('/', slash1 + 1);
            const std::string_view vt = text.substr(
                slash1 + 1, slash2 == std::string_view::npos ? std::string_view::npos : slash2 - slash1 - 1);
            if (!vt.empty()) {
                c.vt = index(vt, token, texcoords_.size(), "texture coordinate", "texture coordinates");
            }
            if (slash2 != std::string_view::npos && slash2 + 1 < text.size()) {
                c.vn = index(text.substr(slash2 + 1), token, normals_.size(), "normal", "normals");
            }
        }
        const auto found = vertex_of_corner_.find(c);
        if (found != vertex_of_corner_.end()) {
            return found->second;
        }
        check_room(mesh_.positions.size(), limits_.max_vertices, token,
                   "vertices (distinct position, texture coordinate and normal triples)");
        const auto vertex = static_cast<std::uint32_t>(mesh_.positions.size());
        vertex_of_corner_.emplace(c, vertex);
        mesh_.positions.push_back(positions_[c.v]);
        // A corner without a normal gets NaN: the mesh recomputes it from the geometry.
        mesh_.normals.push_back(c.vn == kNone ? Vec3{kNaN, kNaN, kNaN} : normals_[c.vn]);
        any_normal_ = any_normal_ || c.vn != kNone;
        // A corner without a texture coordinate gets (0, 0), as other renderers give it.
        mesh_.uvs.push_back(c.vt == kNone ? Point2{0, 0} : texcoords_[c.vt]);
        any_uv_ = any_uv_ || c.vt != kNone;
        return vertex;
    }

    // The rest of the line after the keyword, as one name (`usemtl`, whose names may hold spaces).
    std::string_view rest_of(std::string_view line, const Token& keyword) const {
        std::size_t begin = keyword.column + keyword.text.size();
        while (begin < line.size() && (line[begin] == ' ' || line[begin] == '\t')) {
            ++begin;
        }
        std::size_t end = line.size();
        while (end > begin && (line[end - 1] == ' ' || line[end - 1] == '\t' || line[end - 1] == '\r')) {
            --end;
        }
        return line.substr(begin, end - begin);
    }

    void use_material(std::string_view line, const Token& keyword) {
        const std::string name(rest_of(line, keyword));
        if (name.empty()) {
            fail(keyword, "'usemtl' needs a material name");
        }
        const auto [found, added] =
            material_index_.emplace(name, static_cast<std::uint32_t>(materials_->materials.size()));
        if (added) {
            materials_->materials.push_back({name, position(keyword)});
        }
        current_material_ = found->second;
    }

    void parse_line(std::string_view line) {
        const std::size_t comment = line.find('#');
        if (comment != std::string_view::npos) {
            line = line.substr(0, comment);
        }
        Words words(line);
        Token keyword;
        if (!words.next(keyword)) {
            return;
        }
        if (keyword.text == "v") {
            check_room(positions_.size(), limits_.max_vertices, keyword, "vertex positions");
            positions_.push_back(vec3(words, keyword, kMaxMeshCoordinate, "vertex"));
        } else if (keyword.text == "vt") {
            check_room(texcoords_.size(), limits_.max_vertices, keyword, "texture coordinates");
            Token token;
            double uv[2] = {0, 0};  // v may be left out (a 1D texture), and w is not used
            for (int i = 0; i < 2; ++i) {
                if (!words.next(token)) {
                    if (i == 0) {
                        fail(keyword, "'vt' needs at least one number");
                    }
                    break;
                }
                uv[i] = number(token);
            }
            texcoords_.push_back({uv[0], uv[1]});
        } else if (keyword.text == "vn") {
            check_room(normals_.size(), limits_.max_vertices, keyword, "normals");
            // Any finite normal will do: one too long to normalise is recomputed, like a zero one.
            normals_.push_back(vec3(words, keyword, std::numeric_limits<double>::max(), "normal"));
        } else if (keyword.text == "f") {
            // A fan, corner by corner: (first, previous, current) for every corner after the second.
            Token token;
            std::uint32_t fan[2] = {0, 0};
            std::size_t corners = 0;
            while (words.next(token)) {
                const std::uint32_t current = corner(token);
                if (corners >= 2) {
                    check_room(mesh_.triangles.size(), limits_.max_triangles, token, "triangles");
                    mesh_.triangles.push_back({fan[0], fan[1], current});
                    if (materials_) {
                        materials_->triangle_material.push_back(current_material_);
                    }
                }
                fan[corners == 0 ? 0 : 1] = current;
                ++corners;
            }
            if (corners < 3) {
                fail(keyword, "a face needs at least three corners");
            }
        } else if (materials_ && keyword.text == "usemtl") {
            use_material(line, keyword);
        } else if (materials_ && keyword.text == "mtllib") {
            Token file;
            while (words.next(file)) {
                materials_->libraries.push_back({std::string(file.text), position(file)});
            }
        }
        // Anything else (o, g, s, l, p, …) does not change the surface.
    }

    static constexpr std::uint32_t kNone = 0xffffffffu;
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

    std::string path_;
    std::string text_;
    MeshLimits limits_;
    std::uint64_t line_number_ = 0;
    std::size_t line_start_ = 0;
    std::vector<Vec3> positions_;
    std::vector<Vec3> normals_;
    std::vector<Point2> texcoords_;
    std::unordered_map<Corner, std::uint32_t, CornerHash> vertex_of_corner_;
    bool any_normal_ = false;
    bool any_uv_ = false;
    MeshData mesh_;
    ObjMaterialUse* materials_ = nullptr;
    std::unordered_map<std::string, std::uint32_t> material_index_;
    std::uint32_t current_material_ = ObjMaterialUse::kNoMaterial;
};

}  // namespace

MeshData load_obj(const std::filesystem::path& path, const MeshLimits& limits, const SourcePos& mentioned_at,
                  ObjMaterialUse* materials) {
    if (materials) {
        *materials = {};
    }
    return ObjParser(path.string(), mesh_io::read_file(path, mentioned_at, limits.max_file_bytes), limits,
                     materials)
        .parse();
}

}  // namespace glint
