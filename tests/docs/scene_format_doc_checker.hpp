// Checks that docs/scene-format.md, the user's truth, agrees with the code (glint issue 12, "docs that
// cannot drift"). The checks return problems rather than asserting, so that tests can also run them on
// broken copies of the doc and see that they fail.
//
// The conventions the doc follows for these checks (the doc repeats them in a comment at its top):
// - A chapter is a `## title` heading. A concept (shapes, materials, …) has a chapter, and in it one
//   section per name of its name → constructor table, headed by the name in backticks: ### `sphere`.
//   Names that share a section (aliases) share its heading: ### `metal`, `glossy`. A section runs to
//   the next heading of its level or above.
// - A key is mentioned in a section when it is a word of an inline code span (`radius`, or `radiance:
//   [r, g, b]`) in the section's text outside ```yaml blocks, or in its chapter's introduction (the text
//   before the chapter's first subsection, where keys every type of the chapter takes belong).
// - Every ```yaml block is a whole scene, built with docs/ as the scene's folder. A comment on the line
//   before the fence changes that: <!-- fragment: objects --> makes the block the value of the
//   top-level key `objects` of an otherwise empty scene; <!-- error: TEXT --> says the block must fail
//   to load or build with a message that holds TEXT.
#pragma once

#include <cstddef>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace glint::doc_check {

// One ```yaml block.
struct YamlBlock {
    int line = 0;        // of the opening fence, 1-based
    std::string text;    // between the fences
    std::string marker;  // the comment on the line before the fence, without <!-- -->; "" if none
};

// A heading and its own text, up to the next heading of any level.
struct Heading {
    int level = 0;  // 1 for `#`, 2 for `##`, …; 0 for the text before the first heading
    int line = 0;
    std::string title;
    std::vector<std::string> names;    // the names a name heading (### `metal`, `glossy`) lists
    std::set<std::string> code_words;  // the words of the inline code spans of its own text
    std::vector<YamlBlock> blocks;
};

struct MarkdownDoc {
    std::string path;  // for messages
    std::vector<Heading> headings;

    // One past the last heading inside the section of headings[index] (its subsections included).
    std::size_t section_end(std::size_t index) const;
    // The code words of the whole section of headings[index].
    std::set<std::string> section_words(std::size_t index) const;
    // The index of the `## title` heading (ignoring case), or npos.
    std::size_t chapter(const std::string& title) const;
    // "scene-format.md:LINE".
    std::string where(int line) const;
};

MarkdownDoc parse_markdown(const std::string& text, const std::string& display_path);

// A kind of scene object with a name → constructor table, and where the doc describes it.
struct Concept {
    std::string chapter;                      // the `## ` heading, e.g. "objects"
    std::vector<std::string> names;           // the names in its table
    std::vector<std::string> optional_names;  // documented although this build may lack them (embree)
    // Written as a map {type: NAME, …}: each name's section must show one in a ```yaml block, and every
    // key the code asks of such a map, anywhere in the doc, must be mentioned in the name's section.
    bool written_as_map = false;
    // Folders (under the source tree) whose Params getters' string-literal keys the chapter must mention:
    // this catches keys that are only asked on some branch the doc's examples do not take.
    std::vector<std::string> source_dirs;
};

// The scene's concepts, their names read from the tables (shape_table(), material_table(), …).
std::vector<Concept> scene_concepts();

// A map at a fixed place in every scene, and the chapter that must mention every key asked of it.
// An empty path is the top level, whose chapter "" is the doc's introduction (before the first `##`).
struct PlacedMap {
    std::vector<std::string> path;
    std::string chapter;
};

// The top level, `render:` and `render.filter`. Add a row when another fixed block gets keys of its own.
std::vector<PlacedMap> placed_maps();

// Every name has a section in its concept's chapter, and every name heading there names a known name.
std::vector<std::string> check_sections(const MarkdownDoc& doc, const std::vector<Concept>& concepts);

// Every ```yaml block loads and builds (or fails as its <!-- error: … --> marker says).
std::vector<std::string> check_blocks_build(const MarkdownDoc& doc, const std::filesystem::path& base_dir);

// Builds every block with an AskedKeyRecorder and checks that each key asked of a typed map (and of a
// placed map) is mentioned where it belongs, and that each map-written name has an example of its own.
std::vector<std::string> check_asked_keys(const MarkdownDoc& doc, const std::vector<Concept>& concepts,
                                          const std::vector<PlacedMap>& placed,
                                          const std::filesystem::path& base_dir);

// The keys a concept's sources pass as string literals to Params getters (and read_texture /
// read_reflectance) are mentioned in its chapter.
std::vector<std::string> check_source_keys(const MarkdownDoc& doc, const std::vector<Concept>& concepts,
                                           const std::filesystem::path& source_dir);

// The functions that take a key, as the headers declare them, so that a new getter is scanned too.
struct KeyReaders {
    std::set<std::string> members;    // of Params: number(const std::string& key, …), has, fail, …
    std::set<std::string> functions;  // read_texture(Params& params, const std::string& key, …), …
};
KeyReaders key_readers(const std::filesystem::path& source_dir);

// The string literals passed as a key in C++ source text: `x.number("key", …)`, `p->has("key")`,
// `read_reflectance(params, "key", …)`, also across line breaks.
std::set<std::string> keys_in_source(const std::string& source, const KeyReaders& readers);

}  // namespace glint::doc_check
