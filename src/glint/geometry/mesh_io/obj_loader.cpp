// Wavefront OBJ: `v x y z [w]`, `vn x y z` and `f` with v, v/vt, v//vn or v/vt/vn corners (1-based;
// negative indices count back from the latest vertex). Polygons of any size are split into a fan.
// Texture coordinates, groups, materials and other statements are read past. Corners that share a
// position but not a normal become separate vertices, so the normals can be interpolated per vertex.
#include <charconv>
#include <cmath>
#include <limits>
#include <unordered_map>

#include "glint/geometry/mesh_io/mesh_data.hpp"

namespace glint {
namespace {

class ObjParser {
  public:
    ObjParser(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {}

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

    [[noreturn]] void fail(std::size_t column, const std::string& message) const {
        const SourcePos pos{SourceFile::from_text(path_, text_), line_number_, static_cast<int>(column) + 1};
        throw SceneError(pos, message);
    }
    [[noreturn]] void fail(const Token& token, const std::string& message) const {
        fail(token.text.data() - text_.data() - line_start_, message);
    }

    static std::vector<Token> split(std::string_view line) {
        std::vector<Token> tokens;
        std::size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) {
                ++i;
            }
            const std::size_t begin = i;
            while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') {
                ++i;
            }
            if (i > begin) {
                tokens.push_back({line.substr(begin, i - begin), begin});
            }
        }
        return tokens;
    }

    double number(const Token& token) const {
        double value = 0;
        const char* first = token.text.data();
        const char* last = first + token.text.size();
        if (*first == '+') {
            ++first;  // from_chars does not take a leading '+'
        }
        const auto [end, error] = std::from_chars(first, last, value);
        if (error != std::errc() || end != last) {
            fail(token, "expected a number, found '" + std::string(token.text) + "'");
        }
        if (!std::isfinite(value)) {
            fail(token, "the number '" + std::string(token.text) + "' is not finite");
        }
        return value;
    }

    Vec3 vec3(const std::vector<Token>& tokens, const char* what) const {
        if (tokens.size() < 4) {
            fail(tokens[0], std::string("'") + what + "' needs three numbers");
        }
        return {number(tokens[1]), number(tokens[2]), number(tokens[3])};
    }

    // A 1-based or negative index into a list of `count` items, as a 0-based index.
    std::uint32_t index(std::string_view text, const Token& token, std::size_t count,
                        const char* what) const {
        long long value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size()) {
            fail(token, std::string("expected a ") + what + " index, found '" + std::string(text) + "'");
        }
        const long long n = static_cast<long long>(count);
        const long long resolved = value > 0 ? value - 1 : n + value;
        if (value == 0 || resolved < 0 || resolved >= n) {
            fail(token, std::string(what) + " index " + std::to_string(value) +
                            " is out of range (there are " + std::to_string(count) + " " + what +
                            "s so far)");
        }
        return static_cast<std::uint32_t>(resolved);
    }

    // The mesh vertex of a face corner "v", "v/vt", "v//vn" or "v/vt/vn".
    std::uint32_t corner(const Token& token) {
        const std::string_view text = token.text;
        const std::size_t slash1 = text.find('/');
        const std::uint32_t v = index(text.substr(0, slash1), token, positions_.size(), "vertex");
        std::uint32_t n = kNoNormal;
        if (slash1 != std::string_view::npos) {
            const std::size_t slash2 = text.find('/', slash1 + 1);
            if (slash2 != std::string_view::npos && slash2 + 1 < text.size()) {
                n = index(text.substr(slash2 + 1), token, normals_.size(), "normal");
            }
        }
        const std::uint64_t key = (static_cast<std::uint64_t>(v) << 32) | n;
        const auto [it, inserted] =
            vertex_of_corner_.try_emplace(key, static_cast<std::uint32_t>(mesh_.positions.size()));
        if (inserted) {
            mesh_.positions.push_back(positions_[v]);
            // A corner without a normal gets NaN: the mesh recomputes it from the geometry.
            mesh_.normals.push_back(n == kNoNormal ? Vec3{kNaN, kNaN, kNaN} : normals_[n]);
            any_normal_ = any_normal_ || n != kNoNormal;
        }
        return it->second;
    }

    void parse_line(std::string_view line) {
        const std::size_t comment = line.find('#');
        if (comment != std::string_view::npos) {
            line = line.substr(0, comment);
        }
        const std::vector<Token> tokens = split(line);
        if (tokens.empty()) {
            return;
        }
        const std::string_view keyword = tokens[0].text;
        if (keyword == "v") {
            positions_.push_back(vec3(tokens, "v"));
        } else if (keyword == "vn") {
            normals_.push_back(vec3(tokens, "vn"));
        } else if (keyword == "f") {
            if (tokens.size() < 4) {
                fail(tokens[0], "a face needs at least three corners");
            }
            const std::uint32_t first = corner(tokens[1]);
            std::uint32_t previous = corner(tokens[2]);
            for (std::size_t i = 3; i < tokens.size(); ++i) {
                const std::uint32_t current = corner(tokens[i]);
                mesh_.triangles.push_back({first, previous, current});
                previous = current;
            }
        }
        // Anything else (vt, o, g, s, usemtl, mtllib, l, p, …) does not change the surface.
    }

    static constexpr std::uint32_t kNoNormal = 0xffffffffu;
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

    std::string path_;
    std::string text_;
    int line_number_ = 0;
    std::size_t line_start_ = 0;
    std::vector<Vec3> positions_;
    std::vector<Vec3> normals_;
    std::unordered_map<std::uint64_t, std::uint32_t> vertex_of_corner_;
    bool any_normal_ = false;
    MeshData mesh_;
};

}  // namespace

MeshData load_obj(const std::filesystem::path& path) {
    return ObjParser(path.string(), mesh_io::read_file(path)).parse();
}

}  // namespace glint
