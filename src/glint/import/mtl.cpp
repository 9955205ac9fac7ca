// MTL: `newmtl name`, then statements of one keyword and its values a line (# starts a comment).
// Read here: Kd, Ks, Ke, Tf (r [g b], each in [0, ∞)), Ns, Ni, d, Tr, illum and map_Kd (the last word
// of the line is the file; the options before it, -s, -o, -bm, …, are reported as ignored).
#include "glint/import/mtl.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <set>

#include "glint/geometry/mesh_io/mesh_data.hpp"

namespace glint {
namespace {

class MtlParser {
  public:
    MtlParser(std::string path, std::string text) : path_(std::move(path)), text_(std::move(text)) {
        file_ = SourceFile::from_text(path_, text_);
    }

    std::vector<MtlMaterial> parse() {
        std::size_t start = 0;
        int line_number = 0;
        while (start < text_.size()) {
            std::size_t end = text_.find('\n', start);
            if (end == std::string::npos) {
                end = text_.size();
            }
            ++line_number;
            parse_line(std::string_view(text_).substr(start, end - start), line_number);
            start = end + 1;
        }
        return std::move(materials_);
    }

  private:
    struct Word {
        std::string_view text;
        int column = 0;  // 1-based
    };

    static std::vector<Word> words_of(std::string_view line) {
        std::vector<Word> words;
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
                words.push_back({line.substr(begin, i - begin), static_cast<int>(begin) + 1});
            }
        }
        return words;
    }

    SourcePos at(const Word& word) const { return {file_, line_, word.column}; }

    [[noreturn]] void fail(const Word& word, const std::string& message) const {
        throw SceneError(at(word), message);
    }

    double number(const Word& word) const {
        double value = 0;
        const char* first = word.text.data();
        const char* last = first + word.text.size();
        if (first != last && *first == '+') {
            ++first;
        }
        const auto [end, error] = std::from_chars(first, last, value);
        if (error != std::errc() || end != last || !std::isfinite(value)) {
            fail(word, "expected a finite number, found '" + std::string(word.text) + "'");
        }
        return value;
    }

    // `Kd r [g b]`: one number is grey. `spectral` and `xyz` forms are refused.
    Rgb colour(const std::vector<Word>& words) const {
        if (words.size() < 2) {
            fail(words[0],
                 std::string("'").append(words[0].text).append("' needs a colour: r g b, or one number"));
        }
        if (words[1].text == "spectral" || words[1].text == "xyz") {
            fail(words[1],
                 std::string("'").append(words[1].text).append("' colours are not supported: give r g b"));
        }
        const double r = number(words[1]);
        const double g = words.size() > 2 ? number(words[2]) : r;
        const double b = words.size() > 3 ? number(words[3]) : r;
        if (r < 0 || g < 0 || b < 0) {
            fail(words[1], std::string("'").append(words[0].text).append("' must not be negative"));
        }
        return {r, g, b};
    }

    double one_number(const std::vector<Word>& words) const {
        if (words.size() < 2) {
            fail(words[0], std::string("'").append(words[0].text).append("' needs a number"));
        }
        return number(words[1]);
    }

    void parse_line(std::string_view line, int line_number) {
        line_ = line_number;
        const std::size_t comment = line.find('#');
        const std::vector<Word> words =
            words_of(comment == std::string_view::npos ? line : line.substr(0, comment));
        if (words.empty()) {
            return;
        }
        const std::string keyword(words[0].text);
        if (keyword == "newmtl") {
            if (words.size() < 2) {
                fail(words[0], "'newmtl' needs a material name");
            }
            const std::size_t begin = static_cast<std::size_t>(words[1].column - 1);
            const std::size_t end =
                static_cast<std::size_t>(words.back().column - 1) + words.back().text.size();
            MtlMaterial material;
            material.name = std::string(line.substr(begin, end - begin));
            material.pos = at(words[0]);
            materials_.push_back(std::move(material));
            ignored_keywords_.clear();
            return;
        }
        if (materials_.empty()) {
            fail(words[0], "'" + keyword + "' before any 'newmtl': every statement belongs to a material");
        }
        MtlMaterial& m = materials_.back();
        const SourcePos pos = at(words[0]);
        if (keyword == "Kd") {
            m.kd = {colour(words), pos};
        } else if (keyword == "Ks") {
            m.ks = {colour(words), pos};
        } else if (keyword == "Ke") {
            m.ke = {colour(words), pos};
        } else if (keyword == "Tf") {
            m.tf = {colour(words), pos};
        } else if (keyword == "Ns") {
            m.ns = {one_number(words), pos};
        } else if (keyword == "Ni") {
            m.ni = {one_number(words), pos};
        } else if (keyword == "d" || keyword == "Tr") {
            // `d -halo` is a view-dependent dissolve: the number is the last word.
            const double value = words.size() < 2 ? -1 : number(words.back());
            if (value < 0 || value > 1) {
                fail(words.back(), "'" + keyword + "' needs a number from 0 to 1");
            }
            m.d = {keyword == "d" ? value : 1 - value, pos};
        } else if (keyword == "illum") {
            const double value = one_number(words);
            if (value != std::floor(value) || value < 0 || value > 10) {
                fail(words[1], "'illum' needs a whole number from 0 to 10");
            }
            m.illum = {static_cast<int>(value), pos};
        } else if (keyword == "map_Kd") {
            if (words.size() < 2) {
                fail(words[0], "'map_Kd' needs a file name");
            }
            m.map_kd = {std::string(words.back().text), at(words.back())};
            if (words.size() > 2) {
                m.ignored.push_back({"map_Kd options (" + std::string(words[1].text) + " …)", at(words[1])});
            }
        } else if (ignored_keywords_.insert(keyword).second) {
            m.ignored.push_back({keyword, pos});
        }
    }

    std::string path_;
    std::string text_;
    std::shared_ptr<const SourceFile> file_;
    int line_ = 0;
    std::vector<MtlMaterial> materials_;
    std::set<std::string> ignored_keywords_;  // of the current material, so each is reported once
};

}  // namespace

std::vector<MtlMaterial> load_mtl(const std::filesystem::path& path, const SourcePos& mentioned_at,
                                  std::uint64_t max_bytes) {
    return MtlParser(path.string(), mesh_io::read_file(path, mentioned_at, max_bytes)).parse();
}

}  // namespace glint
