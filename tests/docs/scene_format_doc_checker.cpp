#include "docs/scene_format_doc_checker.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <tuple>

#include "glint/accel/accelerator.hpp"
#include "glint/camera/camera.hpp"
#include "glint/geometry/shape.hpp"
#include "glint/integrator/integrator.hpp"
#include "glint/light/light.hpp"
#include "glint/material/material.hpp"
#include "glint/params/params.hpp"
#include "glint/sampling/sampler.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/texture/texture.hpp"

namespace glint::doc_check {

namespace {

std::string trim(const std::string& s) {
    const auto begin = s.find_first_not_of(" \t\r");
    if (begin == std::string::npos) {
        return "";
    }
    return s.substr(begin, s.find_last_not_of(" \t\r") - begin + 1);
}

bool starts_with(const std::string& s, const std::string& prefix) {
    return s.compare(0, prefix.size(), prefix) == 0;
}

bool is_word_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

std::string lower(std::string s) {
    for (char& c : s) {
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return s;
}

// The contents of the inline code spans of one line: `x` and ``x`` (a run of n backticks closes on the
// next run of exactly n). A backtick run with no partner opens no span.
std::vector<std::string> code_spans(const std::string& line) {
    std::vector<std::string> spans;
    std::size_t i = 0;
    while ((i = line.find('`', i)) != std::string::npos) {
        std::size_t run = 0;
        while (i + run < line.size() && line[i + run] == '`') {
            ++run;
        }
        const std::size_t content = i + run;
        std::size_t close = content;
        bool found = false;
        while ((close = line.find('`', close)) != std::string::npos) {
            std::size_t close_run = 0;
            while (close + close_run < line.size() && line[close + close_run] == '`') {
                ++close_run;
            }
            if (close_run == run) {
                found = true;
                break;
            }
            close += close_run;
        }
        if (!found) {
            break;
        }
        spans.push_back(line.substr(content, close - content));
        i = close + run;
    }
    return spans;
}

// The words of a code span: runs of letters, digits and '_', '-', '.', so that `ambient-occlusion` is
// one word, `--seed` (a flag) does not mention the key `seed`, nor `render.max_depth` an integrator's
// own `max_depth`.
void add_words(const std::string& text, std::set<std::string>& words) {
    std::string word;
    for (const char c : text + " ") {
        if (is_word_char(c) || c == '-' || c == '.') {
            word += c;
        } else if (!word.empty()) {
            words.insert(word);
            word.clear();
        }
    }
}

// The names of a name heading (### `metal`, `glossy`): its code spans, when nothing but commas and
// spaces lies between them. Any other heading lists no names.
std::vector<std::string> heading_names(const std::string& title) {
    std::vector<std::string> names = code_spans(title);
    std::string rest = title;
    for (const std::string& name : names) {
        const auto at = rest.find("`" + name + "`");
        if (at != std::string::npos) {
            rest.erase(at, name.size() + 2);
        }
    }
    if (rest.find_first_not_of(", ") != std::string::npos) {
        return {};
    }
    return names;
}

// The marker text of a line `<!-- text -->`, or "".
std::string marker_of(const std::string& trimmed_line) {
    if (!starts_with(trimmed_line, "<!--") || trimmed_line.size() < 7 ||
        trimmed_line.compare(trimmed_line.size() - 3, 3, "-->") != 0) {
        return "";
    }
    return trim(trimmed_line.substr(4, trimmed_line.size() - 7));
}

// The part of a marker after `kind:`, or nullopt when the marker is of another kind.
std::optional<std::string> marker_argument(const std::string& marker, const std::string& kind) {
    if (!starts_with(marker, kind + ":")) {
        return std::nullopt;
    }
    return trim(marker.substr(kind.size() + 1));
}

// A block loaded and built, with every key the code asked on the way.
struct BuiltBlock {
    std::unique_ptr<SceneDesc> desc;
    bool built = false;
    std::string message;  // why it failed: the SceneError's message, or the exception's what()
    std::string report;   // the whole diagnostic, for problems
    std::vector<AskedKeyRecorder::Ask> asks;
};

BuiltBlock build_block(const MarkdownDoc& doc, const YamlBlock& block,
                       const std::filesystem::path& base_dir) {
    std::string text = block.text;
    if (const auto key = marker_argument(block.marker, "fragment")) {
        // The block becomes the value of `key`: indent it under the key.
        std::istringstream lines(block.text);
        text = *key + ":\n";
        for (std::string line; std::getline(lines, line);) {
            text += "  " + line + "\n";
        }
    }
    BuiltBlock out;
    AskedKeyRecorder recorder;
    try {
        out.desc = std::make_unique<SceneDesc>(
            parse_scene_text(text, doc.where(block.line) + " (yaml block)", base_dir));
        static_cast<void>(build_scene(*out.desc));
        out.built = true;
    } catch (const SceneError& e) {
        out.message = e.message();
        out.report = e.what();
    } catch (const std::exception& e) {
        out.message = out.report = e.what();
    }
    out.asks = recorder.asks();
    return out;
}

// A map told by where it begins and by its keys, as AskedKeyRecorder records it: a copy the builder
// makes of a map of the description is the same map; a map the builder makes up at the same place
// (the default integrator at `render:`'s position) is not.
using MapIdentity = std::tuple<const SourceFile*, int, int, std::vector<std::string>>;

MapIdentity identity(const SourcePos& pos, const std::vector<std::string>& keys) {
    return {pos.file.get(), pos.line, pos.column, keys};
}

// Every map in the tree under `node`, by identity.
void collect_maps(const Node& node, std::map<MapIdentity, const Node*>& maps) {
    if (node.is_map()) {
        maps.emplace(identity(node.pos, node.keys), &node);
    }
    for (const Node& item : node.items) {
        collect_maps(item, maps);
    }
}

// The scalar `type` of a map, or "".
std::string type_of(const Node& map) {
    const Node* type = map.find("type");
    return type && type->is_scalar() ? type->scalar : "";
}

const Node* find_path(const Node& root, const std::vector<std::string>& path) {
    const Node* node = &root;
    for (const std::string& key : path) {
        node = node->is_map() ? node->find(key) : nullptr;
        if (!node) {
            return nullptr;
        }
    }
    return node;
}

// The code words of a chapter; "" is the doc's introduction, everything before the first `##`.
std::set<std::string> chapter_words(const MarkdownDoc& doc, const std::string& title) {
    if (!title.empty()) {
        const std::size_t chapter = doc.chapter(title);
        return chapter == std::string::npos ? std::set<std::string>{} : doc.section_words(chapter);
    }
    std::set<std::string> words;
    for (const Heading& h : doc.headings) {
        if (h.level >= 2) {
            break;
        }
        words.insert(h.code_words.begin(), h.code_words.end());
    }
    return words;
}

std::string describe_chapter(const std::string& title) {
    return title.empty() ? "the introduction (before the first ## heading)" : "## " + title;
}

std::string describe_path(const std::vector<std::string>& path) {
    if (path.empty()) {
        return "the top level";
    }
    std::string s = "`";
    for (std::size_t i = 0; i < path.size(); ++i) {
        s += (i ? "." : "") + path[i];
    }
    return s + ":`";
}

template <typename Table>
std::vector<std::string> names_of(const Table& table) {
    std::vector<std::string> names;
    for (const auto& entry : table) {
        names.emplace_back(entry.name);
    }
    return names;
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

std::size_t MarkdownDoc::section_end(std::size_t index) const {
    std::size_t end = index + 1;
    while (end < headings.size() && headings[end].level > headings[index].level) {
        ++end;
    }
    return end;
}

std::set<std::string> MarkdownDoc::section_words(std::size_t index) const {
    std::set<std::string> words;
    for (std::size_t i = index; i < section_end(index); ++i) {
        words.insert(headings[i].code_words.begin(), headings[i].code_words.end());
    }
    return words;
}

std::size_t MarkdownDoc::chapter(const std::string& title) const {
    for (std::size_t i = 0; i < headings.size(); ++i) {
        if (headings[i].level == 2 && lower(headings[i].title) == lower(title)) {
            return i;
        }
    }
    return std::string::npos;
}

std::string MarkdownDoc::where(int line) const {
    return path + ":" + std::to_string(line);
}

MarkdownDoc parse_markdown(const std::string& text, const std::string& display_path) {
    MarkdownDoc doc;
    doc.path = display_path;
    doc.headings.push_back(Heading{0, 1, "", {}, {}, {}});
    std::istringstream lines(text);
    bool in_fence = false;
    bool in_yaml = false;
    bool in_comment = false;
    YamlBlock block;
    std::string previous;  // the last non-blank line outside fences, trimmed
    int number = 0;
    for (std::string line; std::getline(lines, line);) {
        ++number;
        const std::string trimmed = trim(line);
        if (in_fence) {
            if (starts_with(trimmed, "```")) {
                if (in_yaml) {
                    doc.headings.back().blocks.push_back(block);
                }
                in_fence = in_yaml = false;
                previous = trimmed;
            } else if (in_yaml) {
                block.text += line + "\n";
            }
            continue;
        }
        // Comments are not prose: their code spans mention nothing. A one-line comment may be a marker.
        if (in_comment) {
            in_comment = trimmed.find("-->") == std::string::npos;
            previous.clear();
            continue;
        }
        if (starts_with(trimmed, "<!--")) {
            in_comment = trimmed.find("-->") == std::string::npos;
            previous = in_comment ? "" : trimmed;
            continue;
        }
        if (starts_with(trimmed, "```")) {
            in_fence = true;
            in_yaml = trim(trimmed.substr(3)) == "yaml";
            block = YamlBlock{number, "", marker_of(previous)};
            continue;
        }
        const std::size_t hashes = line.find_first_not_of('#');
        if (hashes >= 1 && hashes <= 6 && hashes < line.size() && line[hashes] == ' ') {
            Heading heading{static_cast<int>(hashes), number, trim(line.substr(hashes)), {}, {}, {}};
            heading.names = heading_names(heading.title);
            for (const std::string& span : code_spans(heading.title)) {
                add_words(span, heading.code_words);
            }
            doc.headings.push_back(std::move(heading));
            previous = trimmed;
            continue;
        }
        for (const std::string& span : code_spans(line)) {
            add_words(span, doc.headings.back().code_words);
        }
        if (!trimmed.empty()) {
            previous = trimmed;
        }
    }
    if (in_yaml) {
        doc.headings.back().blocks.push_back(block);  // unterminated: check what there is
    }
    return doc;
}

std::vector<Concept> scene_concepts() {
    return {
        {"camera", names_of(camera_table()), {}, true, {"src/glint/camera"}},
        {"materials", names_of(material_table()), {}, true, {"src/glint/material"}},
        {"textures", names_of(texture_table()), {}, true, {"src/glint/texture"}},
        {"objects", names_of(shape_table()), {}, true, {"src/glint/geometry"}},
        {"lights", names_of(light_table()), {}, true, {"src/glint/light"}},
        // render.integrator is {type: NAME, …} with keys of its own (a plain word is the short form).
        {"Integrators", names_of(integrator_table()), {}, true, {"src/glint/integrator"}},
        // render.sampler may be written {type: NAME} too, but a sampler has no keys of its own yet: the
        // plain word is how it is written. Make this true, with examples, when one reads keys.
        {"Samplers", names_of(sampler_table()), {}, false, {}},
        {"Accelerators", names_of(accelerator_table()), {"embree"}, false, {}},
    };
}

std::vector<PlacedMap> placed_maps() {
    return {
        {{}, ""},
        {{"render"}, "render"},
        {{"render", "filter"}, "render"},
    };
}

std::vector<std::string> check_sections(const MarkdownDoc& doc, const std::vector<Concept>& concepts) {
    std::vector<std::string> problems;
    for (const Concept& c : concepts) {
        const std::size_t chapter = doc.chapter(c.chapter);
        if (chapter == std::string::npos) {
            problems.push_back(doc.path + ": no chapter `## " + c.chapter + "`, where " +
                               join_words(c.names) + " belong");
            continue;
        }
        std::set<std::string> documented;
        for (std::size_t i = chapter + 1; i < doc.section_end(chapter); ++i) {
            for (const std::string& name : doc.headings[i].names) {
                documented.insert(name);
                const bool known = std::count(c.names.begin(), c.names.end(), name) ||
                                   std::count(c.optional_names.begin(), c.optional_names.end(), name);
                if (!known) {
                    problems.push_back(doc.where(doc.headings[i].line) + ": section `" + name + "` of ## " +
                                       c.chapter + " names nothing the code knows (it knows " +
                                       join_words(c.names) + ")");
                }
            }
        }
        for (const std::string& name : c.names) {
            if (!documented.count(name)) {
                problems.push_back(doc.where(doc.headings[chapter].line) + ": `" + name +
                                   "` has no section in ## " + c.chapter + ": add a heading ### `" + name +
                                   "` (or add it to the heading of the name it is another name for)");
            }
        }
    }
    return problems;
}

std::vector<std::string> check_blocks_build(const MarkdownDoc& doc, const std::filesystem::path& base_dir) {
    std::vector<std::string> problems;
    for (const Heading& heading : doc.headings) {
        for (const YamlBlock& block : heading.blocks) {
            const std::string where = doc.where(block.line) + ": the yaml block ";
            const auto expected_error = marker_argument(block.marker, "error");
            if (!block.marker.empty() && !expected_error && !marker_argument(block.marker, "fragment")) {
                problems.push_back(where + "has an unknown marker <!-- " + block.marker +
                                   " --> (known: fragment: KEY, error: TEXT)");
                continue;
            }
            const BuiltBlock built = build_block(doc, block, base_dir);
            if (expected_error) {
                if (built.built) {
                    problems.push_back(where + "is marked as an error (" + *expected_error + ") but builds");
                } else if (built.message.find(*expected_error) == std::string::npos) {
                    problems.push_back(where + "fails, but not with '" + *expected_error + "':\n" +
                                       built.report);
                }
            } else if (!built.built) {
                problems.push_back(where + "does not build:\n" + built.report);
            }
        }
    }
    return problems;
}

std::vector<std::string> check_asked_keys(const MarkdownDoc& doc, const std::vector<Concept>& concepts,
                                          const std::vector<PlacedMap>& placed,
                                          const std::filesystem::path& base_dir) {
    // The sections of map-written names, and the words each may use: its own and its chapter intro's.
    struct NameSection {
        std::size_t heading;
        std::set<std::string> words;
    };
    std::map<std::string, std::vector<NameSection>> sections;
    for (const Concept& c : concepts) {
        const std::size_t chapter = doc.chapter(c.chapter);
        if (!c.written_as_map || chapter == std::string::npos) {
            continue;  // check_sections reports a missing chapter
        }
        for (std::size_t i = chapter + 1; i < doc.section_end(chapter); ++i) {
            for (const std::string& name : doc.headings[i].names) {
                if (std::count(c.names.begin(), c.names.end(), name)) {
                    NameSection s{i, doc.section_words(i)};
                    s.words.insert(doc.headings[chapter].code_words.begin(),
                                   doc.headings[chapter].code_words.end());
                    sections[name].push_back(std::move(s));
                }
            }
        }
    }
    std::vector<std::set<std::string>> placed_words;
    for (const PlacedMap& p : placed) {
        placed_words.push_back(chapter_words(doc, p.chapter));
    }

    std::map<std::string, std::string> problems;  // by what is missing where: each is reported once
    std::set<std::string> shown;                  // names with an example in their own section
    for (std::size_t h = 0; h < doc.headings.size(); ++h) {
        for (const YamlBlock& block : doc.headings[h].blocks) {
            if (marker_argument(block.marker, "error")) {
                continue;
            }
            const BuiltBlock built = build_block(doc, block, base_dir);
            if (!built.built) {
                continue;  // check_blocks_build reports it
            }
            std::map<MapIdentity, const Node*> maps;
            collect_maps(built.desc->root, maps);
            std::map<const Node*, std::size_t> placed_at;
            for (std::size_t i = 0; i < placed.size(); ++i) {
                if (const Node* node = find_path(built.desc->root, placed[i].path)) {
                    placed_at[node] = i;
                }
            }
            for (const AskedKeyRecorder::Ask& ask : built.asks) {
                const auto asked = maps.find(identity(ask.map_pos, ask.map_keys));
                if (asked == maps.end()) {
                    continue;  // a map the builder made up
                }
                if (const auto p = placed_at.find(asked->second); p != placed_at.end()) {
                    if (!placed_words[p->second].count(ask.key)) {
                        problems.emplace(std::to_string(p->second) + " " + ask.key,
                                         doc.where(block.line) + ": key `" + ask.key + "` of " +
                                             describe_path(placed[p->second].path) +
                                             ", asked by the code, is not mentioned in " +
                                             describe_chapter(placed[p->second].chapter));
                    }
                    continue;
                }
                const std::string type = type_of(*asked->second);
                if (!sections.count(type)) {
                    continue;
                }
                for (const NameSection& s : sections.at(type)) {
                    if (!s.words.count(ask.key)) {
                        problems.emplace(
                            type + " " + std::to_string(s.heading) + " " + ask.key,
                            doc.where(doc.headings[s.heading].line) + ": key `" + ask.key + "` of `" + type +
                                "`, asked by the code when building the yaml block at line " +
                                std::to_string(block.line) + ", is not mentioned in its section");
                    }
                }
            }
            for (const auto& [id, map] : maps) {
                const std::string type = type_of(*map);
                if (!sections.count(type)) {
                    continue;
                }
                for (const NameSection& s : sections.at(type)) {
                    if (s.heading <= h && h < doc.section_end(s.heading)) {
                        shown.insert(type);
                    }
                }
            }
        }
    }
    std::vector<std::string> out;
    for (const auto& [id, message] : problems) {
        out.push_back(message);
    }
    for (const auto& [name, list] : sections) {
        if (!shown.count(name)) {
            out.push_back(doc.where(doc.headings[list.front().heading].line) + ": section `" + name +
                          "` has no ```yaml example that builds {type: " + name +
                          ", …}: its keys cannot be checked");
        }
    }
    return out;
}

std::vector<std::string> check_source_keys(const MarkdownDoc& doc, const std::vector<Concept>& concepts,
                                           const std::filesystem::path& source_dir) {
    std::vector<std::string> problems;
    const KeyReaders readers = key_readers(source_dir);
    for (const Concept& c : concepts) {
        const std::set<std::string> words = chapter_words(doc, c.chapter);
        for (const std::string& dir : c.source_dirs) {
            std::vector<std::filesystem::path> files;
            for (const auto& entry : std::filesystem::directory_iterator(source_dir / dir)) {
                if (entry.path().extension() == ".cpp") {
                    files.push_back(entry.path());
                }
            }
            if (files.empty()) {
                problems.push_back(dir + ": no .cpp files to read keys from (moved?)");
            }
            std::sort(files.begin(), files.end());
            for (const auto& file : files) {
                for (const std::string& key : keys_in_source(read_text(file), readers)) {
                    if (!words.count(key)) {
                        problems.push_back(doc.path + ": key `" + key + "`, read in " + dir + "/" +
                                           file.filename().string() + ", is not mentioned in ## " +
                                           c.chapter);
                    }
                }
            }
        }
    }
    return problems;
}

KeyReaders key_readers(const std::filesystem::path& source_dir) {
    // Reads the declarations backwards from `const std::string& key`, one a line, as clang-format
    // writes these short ones: `name(` before it is a member getter of params.hpp; `name(Params& p,`
    // a function in any header. (std::regex would do, but GCC 12 warns inside it under sanitizers.)
    const std::string key_parameter = "const std::string& key";
    const auto trim_end = [](std::string& s) { s.erase(s.find_last_not_of(" \t") + 1); };
    const auto take = [&](std::string& s, const std::string& token) {
        trim_end(s);
        if (s.size() < token.size() || s.compare(s.size() - token.size(), token.size(), token) != 0) {
            return false;
        }
        s.erase(s.size() - token.size());
        return true;
    };
    const auto take_word = [&](std::string& s) {
        trim_end(s);
        std::size_t start = s.size();
        while (start > 0 && is_word_char(s[start - 1])) {
            --start;
        }
        std::string word = s.substr(start);
        s.erase(start);
        return word;
    };
    // Each line's declaration before its key parameter, if it has one.
    const auto declarations = [&](const std::filesystem::path& file) {
        std::vector<std::string> before;
        std::istringstream lines(read_text(file));
        for (std::string line; std::getline(lines, line);) {
            const std::size_t at = line.find(key_parameter);
            const std::size_t after = at + key_parameter.size();
            if (at != std::string::npos && (after == line.size() || !is_word_char(line[after]))) {
                before.push_back(line.substr(0, at));
            }
        }
        return before;
    };
    KeyReaders readers;
    for (std::string before : declarations(source_dir / "src/glint/params/params.hpp")) {
        if (take(before, "(")) {
            if (std::string name = take_word(before); !name.empty()) {
                readers.members.insert(name);
            }
        }
    }
    for (const auto& entry : std::filesystem::recursive_directory_iterator(source_dir / "src/glint")) {
        if (entry.path().extension() != ".hpp") {
            continue;
        }
        for (std::string before : declarations(entry.path())) {
            if (take(before, ",") && !take_word(before).empty() && take(before, "&") &&
                take_word(before) == "Params" && take(before, "(")) {
                if (std::string name = take_word(before); !name.empty()) {
                    readers.functions.insert(name);
                }
            }
        }
    }
    return readers;
}

std::set<std::string> keys_in_source(const std::string& source, const KeyReaders& readers) {
    std::set<std::string> keys;
    const auto skip_space = [&](std::size_t i) {
        while (i < source.size() && std::isspace(static_cast<unsigned char>(source[i]))) {
            ++i;
        }
        return i;
    };
    // The key of a string literal at i: "key" made of word characters, or "".
    const auto literal_at = [&](std::size_t i) -> std::string {
        if (i >= source.size() || source[i] != '"') {
            return "";
        }
        const std::size_t end = source.find('"', i + 1);
        if (end == std::string::npos || end == i + 1) {
            return "";
        }
        const std::string s = source.substr(i + 1, end - i - 1);
        return std::all_of(s.begin(), s.end(), is_word_char) ? s : "";
    };
    std::size_t i = 0;
    while (i < source.size()) {
        if (!is_word_char(source[i]) || (i > 0 && is_word_char(source[i - 1]))) {
            ++i;
            continue;
        }
        std::size_t end = i;
        while (end < source.size() && is_word_char(source[end])) {
            ++end;
        }
        const std::string word = source.substr(i, end - i);
        const bool member =
            (i >= 1 && source[i - 1] == '.') || (i >= 2 && source.compare(i - 2, 2, "->") == 0);
        std::size_t open = skip_space(end);
        if (open < source.size() && source[open] == '(') {
            if (member && readers.members.count(word)) {
                if (std::string key = literal_at(skip_space(open + 1)); !key.empty()) {
                    keys.insert(key);
                }
            } else if (!member && readers.functions.count(word)) {
                // read_texture(params, "key", …): the key is the second argument.
                const std::size_t comma = source.find_first_of(",)", open);
                if (comma != std::string::npos && source[comma] == ',') {
                    if (std::string key = literal_at(skip_space(comma + 1)); !key.empty()) {
                        keys.insert(key);
                    }
                }
            }
        }
        i = end;
    }
    return keys;
}

}  // namespace glint::doc_check
