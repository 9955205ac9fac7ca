// Wavefront OBJ: `v x y z [w]`, `vn x y z` and `f` with v, v/vt, v//vn or v/vt/vn corners (1-based;
// negative indices count back from the latest vertex). Polygons of any size are split into a fan.
// Texture coordinates, groups, materials and other statements are read past. Corners that share a
// position but not a normal become separate vertices, so the normals can be interpolated per vertex.
//
// Hostile files: lines are read word by word, never split into a list first (a line of a billion
// corners costs only the triangles it makes); every count is checked against MeshLimits before it
// grows; coordinates must be finite and within float's range (kMaxMeshCoordinate).
#include <charconv>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "glint/geometry/mesh_io/mesh_data.hpp"

namespace glint {
namespace {

class ObjParser {
  public:
    ObjParser(std::string path, std::string text, const MeshLimits& limits)
        : path_(std::move(path)), text_(std::move(text)), limits_(limits) {}

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

    [[noreturn]] void fail(std::size_t column, const std::string& message) const {
        // Positions are ints; a file within the size limit could have more lines or longer ones.
        constexpr std::uint64_t kIntMax = std::numeric_limits<int>::max();
        // Only the offending line is kept for the report: the file may be gigabytes.
        const std::size_t line_end = std::min(text_.find('\n', line_start_), text_.size());
        const int line = static_cast<int>(std::min<std::uint64_t>(line_number_, kIntMax));
        const SourcePos pos{
            SourceFile::excerpt(path_, line,
                                std::string_view(text_).substr(line_start_, line_end - line_start_)),
            line, static_cast<int>(std::min<std::uint64_t>(column + 1, kIntMax))};
        throw SceneError(pos, message);
    }
    [[noreturn]] void fail(const Token& token, const std::string& message) const {
        fail(static_cast<std::size_t>(token.text.data() - text_.data()) - line_start_, message);
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

    // The mesh vertex of a face corner "v", "v/vt", "v//vn" or "v/vt/vn".
    std::uint32_t corner(const Token& token) {
        const std::string_view text = token.text;
        const std::size_t slash1 = text.find('/');
        const std::uint32_t v = index(text.substr(0, slash1), token, positions_.size(), "vertex", "vertices");
        std::uint32_t n = kNoNormal;
        if (slash1 != std::string_view::npos) {
            const std::size_t slash2 = text.find('/', slash1 + 1);
            if (slash2 != std::string_view::npos && slash2 + 1 < text.size()) {
                n = index(text.substr(slash2 + 1), token, normals_.size(), "normal", "normals");
            }
        }
        const std::uint64_t key = (static_cast<std::uint64_t>(v) << 32) | n;
        const auto found = vertex_of_corner_.find(key);
        if (found != vertex_of_corner_.end()) {
            return found->second;
        }
        check_room(mesh_.positions.size(), limits_.max_vertices, token,
                   "vertices (distinct position and normal pairs)");
        const auto vertex = static_cast<std::uint32_t>(mesh_.positions.size());
        vertex_of_corner_.emplace(key, vertex);
        mesh_.positions.push_back(positions_[v]);
        // A corner without a normal gets NaN: the mesh recomputes it from the geometry.
        mesh_.normals.push_back(n == kNoNormal ? Vec3{kNaN, kNaN, kNaN} : normals_[n]);
        any_normal_ = any_normal_ || n != kNoNormal;
        return vertex;
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
                }
                fan[corners == 0 ? 0 : 1] = current;
                ++corners;
            }
            if (corners < 3) {
                fail(keyword, "a face needs at least three corners");
            }
        }
        // Anything else (vt, o, g, s, usemtl, mtllib, l, p, …) does not change the surface.
    }

    static constexpr std::uint32_t kNoNormal = 0xffffffffu;
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

    std::string path_;
    std::string text_;
    MeshLimits limits_;
    std::uint64_t line_number_ = 0;
    std::size_t line_start_ = 0;
    std::vector<Vec3> positions_;
    std::vector<Vec3> normals_;
    std::unordered_map<std::uint64_t, std::uint32_t> vertex_of_corner_;
    bool any_normal_ = false;
    MeshData mesh_;
};

}  // namespace

MeshData load_obj(const std::filesystem::path& path, const MeshLimits& limits,
                  const SourcePos& mentioned_at) {
    return ObjParser(path.string(), mesh_io::read_file(path, mentioned_at, limits.max_file_bytes), limits)
        .parse();
}

}  // namespace glint
