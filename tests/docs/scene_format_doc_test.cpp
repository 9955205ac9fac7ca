// docs/scene-format.md is the user's truth: these tests fail when it drifts from the code. Every name of
// every name → constructor table has a section; every key the code asks while building the doc's own
// examples is mentioned where it belongs; every key a concept's sources read is mentioned in its chapter;
// every ```yaml block builds. The conventions are in docs/scene_format_doc_checker.hpp and at the top of
// the doc. The SceneFormatDocChecker tests show that each check fails on a doc that drifted.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <tuple>

#include "docs/scene_format_doc_checker.hpp"
#include "glint/params/params.hpp"
#include "glint/scene/scene_desc.hpp"

namespace glint::doc_check {
namespace {

const std::filesystem::path kSourceDir = GLINT_SOURCE_DIR;
const std::filesystem::path kDocsDir = kSourceDir / "docs";

std::string read_doc_text() {
    std::ifstream in(kDocsDir / "scene-format.md", std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

MarkdownDoc parse(const std::string& text) {
    return parse_markdown(text, "docs/scene-format.md");
}

const MarkdownDoc& real_doc() {
    static const MarkdownDoc doc = parse(read_doc_text());
    return doc;
}

std::string listed(const std::vector<std::string>& problems) {
    std::string s;
    for (const std::string& p : problems) {
        s += "\n  " + p;
    }
    return s;
}

bool any_holds(const std::vector<std::string>& problems, const std::string& text) {
    for (const std::string& p : problems) {
        if (p.find(text) != std::string::npos) {
            return true;
        }
    }
    return false;
}

// The doc with the text between the line `from` and the next heading after it replaced by `with`.
std::string edit_section(std::string text, const std::string& heading, const std::string& from,
                         const std::string& to) {
    const std::size_t begin = text.find("\n" + heading + "\n");
    EXPECT_NE(begin, std::string::npos) << "the doc has no heading " << heading << " to edit";
    if (begin == std::string::npos) {
        return text;
    }
    const std::size_t end = text.find("\n#", begin + 1);
    std::string section = text.substr(begin, end - begin);
    EXPECT_NE(section.find(from), std::string::npos) << heading << " has no '" << from << "' to edit";
    for (std::size_t at; (at = section.find(from)) != std::string::npos;) {
        section.replace(at, from.size(), to);
    }
    return text.substr(0, begin) + section + text.substr(end);
}

std::string without_section(const std::string& text, const std::string& heading) {
    const std::size_t begin = text.find("\n" + heading + "\n");
    EXPECT_NE(begin, std::string::npos) << "the doc has no heading " << heading << " to remove";
    if (begin == std::string::npos) {
        return text;
    }
    return text.substr(0, begin) + text.substr(text.find("\n#", begin + 1));
}

TEST(SceneFormatDoc, FindsItsChaptersAndBlocks) {
    // Guards the checks below against passing on a doc they failed to read.
    const MarkdownDoc& doc = real_doc();
    std::size_t blocks = 0;
    for (const Heading& h : doc.headings) {
        blocks += h.blocks.size();
    }
    EXPECT_GT(doc.headings.size(), 50u);
    EXPECT_GT(blocks, 40u);
    EXPECT_NE(doc.chapter("objects"), std::string::npos);
}

TEST(SceneFormatDoc, EveryTableNameHasASection) {
    const auto problems = check_sections(real_doc(), scene_concepts());
    EXPECT_TRUE(problems.empty()) << listed(problems);
}

TEST(SceneFormatDoc, EveryYamlBlockBuilds) {
    const auto problems = check_blocks_build(real_doc(), kDocsDir);
    EXPECT_TRUE(problems.empty()) << listed(problems);
}

TEST(SceneFormatDoc, EveryKeyTheCodeAsksIsMentioned) {
    const auto problems = check_asked_keys(real_doc(), scene_concepts(), placed_maps(), kDocsDir);
    EXPECT_TRUE(problems.empty()) << listed(problems);
}

TEST(SceneFormatDoc, EveryKeyInTheSourcesIsMentioned) {
    const auto problems = check_source_keys(real_doc(), scene_concepts(), kSourceDir);
    EXPECT_TRUE(problems.empty()) << listed(problems);
}

// --- The checks fail on a doc that drifted.

TEST(SceneFormatDocChecker, ARemovedSectionIsReported) {
    const auto problems =
        check_sections(parse(without_section(read_doc_text(), "### `torus`")), scene_concepts());
    EXPECT_TRUE(any_holds(problems, "`torus` has no section")) << listed(problems);
}

TEST(SceneFormatDocChecker, ARemovedKeyIsReported) {
    // The example still gives minor_radius; only the prose stops naming it.
    const std::string text =
        edit_section(read_doc_text(), "### `torus`", "`minor_radius`", "the minor radius");
    const auto problems = check_asked_keys(parse(text), scene_concepts(), placed_maps(), kDocsDir);
    EXPECT_TRUE(any_holds(problems, "key `minor_radius` of `torus`")) << listed(problems);
    EXPECT_EQ(problems.size(), 1u) << listed(problems);
}

TEST(SceneFormatDocChecker, ARemovedRenderKeyIsReported) {
    const std::string text = edit_section(read_doc_text(), "## render", "`seed`", "seed");
    const auto problems = check_asked_keys(parse(text), scene_concepts(), placed_maps(), kDocsDir);
    EXPECT_TRUE(any_holds(problems, "key `seed` of `render:`")) << listed(problems);
}

TEST(SceneFormatDocChecker, ARemovedFilterKeyIsReported) {
    // render.filter is a map of its own, whose keys belong to the render chapter too.
    std::string text = read_doc_text();
    text = edit_section(text, "## render", "`subpixels`", "the sub-pixel count");
    text = edit_section(text, "## render", "subpixels: S}`", "…}`");
    text = edit_section(text, "## render", "`{type: tent, radius: 0.5, subpixels: 2}`", "its map");
    const auto problems = check_asked_keys(parse(text), scene_concepts(), placed_maps(), kDocsDir);
    EXPECT_TRUE(any_holds(problems, "key `subpixels` of `render.filter:`")) << listed(problems);
    EXPECT_EQ(problems.size(), 1u) << listed(problems);
}

TEST(SceneFormatDocChecker, AnIntegratorsKeyIsChecked) {
    // The builder reads render.integrator through a copy of its map: the key is still the section's.
    std::string text = read_doc_text();
    for (const char* heading : {"## Integrators", "### `whitted`", "### `path`"}) {
        text = edit_section(text, heading, "`max_depth`", "the depth");
    }
    const auto problems = check_asked_keys(parse(text), scene_concepts(), placed_maps(), kDocsDir);
    EXPECT_TRUE(any_holds(problems, "key `max_depth` of `whitted`")) << listed(problems);
    EXPECT_TRUE(any_holds(problems, "key `max_depth` of `path`")) << listed(problems);
}

TEST(SceneFormatDocChecker, AKeyReadOnlyOnABranchIsFoundInTheSource) {
    // `rotation` is only asked when an environment light has an image: the source scan finds it anyway.
    const std::string text = edit_section(read_doc_text(), "### `environment`", "rotation", "turn");
    const auto problems = check_source_keys(parse(text), scene_concepts(), kSourceDir);
    EXPECT_TRUE(any_holds(problems, "key `rotation`, read in src/glint/light/environment.cpp"))
        << listed(problems);
}

TEST(SceneFormatDocChecker, ABrokenExampleIsReported) {
    const std::string text = edit_section(read_doc_text(), "### `torus`", "minor_radius:", "minor_radious:");
    const auto problems = check_blocks_build(parse(text), kDocsDir);
    EXPECT_TRUE(any_holds(problems, "did you mean 'minor_radius'")) << listed(problems);
}

// A small doc with one concept, so that each problem is the only one.
const std::vector<Concept> kSpheres = {{"objects", {"sphere"}, {}, true, {}}};

std::string sphere_doc(const std::string& prose, const std::string& example) {
    return "# t\n\n## objects\n\nEach has a `type`, `material` and `transform`.\n\n### `sphere`\n\n" + prose +
           "\n\n" + example;
}

TEST(SceneFormatDocChecker, KeysAreCheckedAgainstTheNamesSection) {
    const std::string example = "```yaml\nobjects:\n  - {type: sphere, radius: 2}\n```\n";
    EXPECT_TRUE(
        check_asked_keys(parse(sphere_doc("`center`, `radius`.", example)), kSpheres, {}, kDocsDir).empty());
    // center is asked although the example leaves it out: a getter with a default still asks.
    const auto problems = check_asked_keys(parse(sphere_doc("`radius`.", example)), kSpheres, {}, kDocsDir);
    EXPECT_EQ(problems,
              std::vector<std::string>{"docs/scene-format.md:7: key `center` of `sphere`, asked by the code "
                                       "when building the yaml block at line 11, is not mentioned in its "
                                       "section"});
    // Named in the example but not in the prose is not documented.
    EXPECT_TRUE(any_holds(check_asked_keys(parse(sphere_doc("`center`.", example)), kSpheres, {}, kDocsDir),
                          "key `radius` of `sphere`"));
}

TEST(SceneFormatDocChecker, ASectionWithoutAnExampleIsReported) {
    const auto problems =
        check_asked_keys(parse(sphere_doc("`center`, `radius`.", "")), kSpheres, {}, kDocsDir);
    EXPECT_TRUE(any_holds(problems, "section `sphere` has no ```yaml example")) << listed(problems);
}

TEST(SceneFormatDocChecker, AnUnknownNameHeadingIsReported) {
    const std::string text = sphere_doc("`center`, `radius`.", "### `teapot`\n\nA teapot.\n");
    const auto problems = check_sections(parse(text), kSpheres);
    EXPECT_TRUE(any_holds(problems, "section `teapot` of ## objects names nothing the code knows"))
        << listed(problems);
}

TEST(SceneFormatDocChecker, MarkersWrapFragmentsAndExpectErrors) {
    const std::string fragment = "<!-- fragment: objects -->\n```yaml\n- {type: sphere, radius: 1}\n```\n";
    const std::string error =
        "<!-- error: did you mean 'radius' -->\n```yaml\nobjects: [{type: sphere, radious: 1}]\n```\n";
    EXPECT_TRUE(check_blocks_build(parse(sphere_doc("", fragment + error)), kDocsDir).empty());
    // A fragment is not a whole scene; an error block that builds, or fails otherwise, is wrong.
    const std::string unmarked = "```yaml\n- {type: sphere, radius: 1}\n```\n";
    EXPECT_TRUE(any_holds(check_blocks_build(parse(sphere_doc("", unmarked)), kDocsDir), "does not build"));
    const std::string builds =
        "<!-- error: did you mean -->\n```yaml\nobjects: [{type: sphere, radius: 1}]\n```\n";
    EXPECT_TRUE(any_holds(check_blocks_build(parse(sphere_doc("", builds)), kDocsDir), "but builds"));
    const std::string other =
        "<!-- error: did you mean -->\n```yaml\nobjects: [{type: sphere, radius: -1}]\n```\n";
    EXPECT_TRUE(any_holds(check_blocks_build(parse(sphere_doc("", other)), kDocsDir), "fails, but not with"));
    const std::string unknown = "<!-- fragmnet: objects -->\n```yaml\n- {type: sphere, radius: 1}\n```\n";
    EXPECT_TRUE(any_holds(check_blocks_build(parse(sphere_doc("", unknown)), kDocsDir), "unknown marker"));
}

TEST(SceneFormatDocChecker, ParsesHeadingsSpansAndBlocks) {
    const MarkdownDoc doc = parse(
        "intro `a: [b, c]`\n# T\n## ch\ntext ``d`e`` and `f_g`\n### `m`, `n`\n```text\n`no`\n```\n### `m` "
        "and more\n<!-- fragment: objects -->\n```yaml\nx: 1\n```\n");
    ASSERT_EQ(doc.headings.size(), 5u);  // the text before `# T`, then T, ch and the two ###
    EXPECT_EQ(doc.headings[0].code_words, (std::set<std::string>{"a", "b", "c"}));
    EXPECT_EQ(doc.headings[2].code_words, (std::set<std::string>{"d", "e", "f_g"}));
    EXPECT_EQ(doc.headings[3].names, (std::vector<std::string>{"m", "n"}));
    EXPECT_TRUE(doc.headings[3].code_words.count("m"));
    EXPECT_FALSE(doc.headings[3].code_words.count("no"));  // inside a fence
    EXPECT_TRUE(doc.headings[4].names.empty());            // a heading with prose names nothing
    ASSERT_EQ(doc.headings[4].blocks.size(), 1u);
    EXPECT_EQ(doc.headings[4].blocks[0].line, 11);
    EXPECT_EQ(doc.headings[4].blocks[0].marker, "fragment: objects");
    EXPECT_EQ(doc.headings[4].blocks[0].text, "x: 1\n");
    EXPECT_EQ(doc.section_end(2), 5u);
    EXPECT_EQ(doc.chapter("CH"), 2u);
}

TEST(SceneFormatDocChecker, FindsKeysInSource) {
    const KeyReaders readers{{"positive", "vec3", "has", "string"}, {"read_reflectance"}};
    const std::string source = R"(
        const double r = params.positive("radius");
        const Vec3 c = params.vec3(
            "center", {0, 0, 0});
        if (p->has("look_at")) {}
        auto albedo = read_reflectance(params, "albedo", Rgb(0.9), context);
        const std::string s = path.string();
        std::string key = params.string(key_name);
        params.fail("not_a_reader");
        double Params::positive(const std::string& key) { return x.positive("a key"); }
    )";
    EXPECT_EQ(keys_in_source(source, readers),
              (std::set<std::string>{"radius", "center", "look_at", "albedo"}));
}

TEST(SceneFormatDocChecker, FindsTheKeyReadersInTheHeaders) {
    // Guards the source scan against finding no readers (a changed declaration style) and so no keys.
    const KeyReaders readers = key_readers(kSourceDir);
    for (const char* member : {"has", "number", "positive", "enumeration", "node", "child"}) {
        EXPECT_TRUE(readers.members.count(member)) << member;
    }
    for (const char* function : {"read_texture", "read_reflectance"}) {
        EXPECT_TRUE(readers.functions.count(function)) << function;
    }
}

TEST(AskedKeyRecorder, RecordsEveryKeyAskedPresentOrNot) {
    const SceneDesc desc = parse_scene_text("a: 1\nb: {c: 2}\n", "t.yaml", ".");
    Params params(desc.root, "t");
    AskedKeyRecorder outer;
    {
        AskedKeyRecorder inner;
        params.number("a");
        params.number("absent", 2.0);  // a default does not hide the key
        params.has("looked_for");
        params.child("b").number("c", 0.0);
        // Each ask names its map by position and keys: the top level at 1:1, b's map at 2:4.
        std::set<std::tuple<int, int, std::vector<std::string>, std::string>> asked;
        for (const auto& ask : inner.asks()) {
            asked.insert({ask.map_pos.line, ask.map_pos.column, ask.map_keys, ask.key});
        }
        const std::vector<std::string> top{"a", "b"};
        EXPECT_EQ(asked, (std::set<std::tuple<int, int, std::vector<std::string>, std::string>>{
                             {1, 1, top, "a"},
                             {1, 1, top, "absent"},
                             {1, 1, top, "looked_for"},
                             {1, 1, top, "b"},
                             {2, 4, {"c"}, "c"}}));
    }
    EXPECT_TRUE(outer.asks().empty());  // the inner recorder hid the outer one
    params.has("later");
    ASSERT_EQ(outer.asks().size(), 1u);
    EXPECT_EQ(outer.asks()[0].key, "later");
}

}  // namespace
}  // namespace glint::doc_check
