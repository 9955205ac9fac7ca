// The generic name tables: concept tables (name → constructor) and enum tables (name ↔ value), their
// positioned did-you-mean errors, and the one build step (lookup, create, unused-key check).
#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "glint/accel/accelerator.hpp"
#include "glint/camera/camera.hpp"
#include "glint/integrator/integrator.hpp"
#include "glint/light/light.hpp"
#include "glint/material/material.hpp"
#include "glint/params/name_table.hpp"
#include "glint/sampling/sampler.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/texture/texture.hpp"

namespace glint {
namespace {

// A concept of the test's own: a widget is built from its parameters and one extra argument.
struct Widget {
    std::string kind;
    double size = 0;
    int extra = 0;
};
using WidgetFactory = std::unique_ptr<Widget> (*)(Params&, int extra);
struct WidgetEntry {
    std::string name;
    WidgetFactory create;
};

std::unique_ptr<Widget> make_knob(Params& params, int extra) {
    return std::make_unique<Widget>(Widget{"knob", params.number("size", 1), extra});
}
std::unique_ptr<Widget> make_lever(Params& params, int extra) {
    return std::make_unique<Widget>(Widget{"lever", params.positive("size"), extra});
}

const NameTable<WidgetEntry>& widget_table() {
    static const NameTable<WidgetEntry> table = {
        {"knob", &make_knob},
        {"lever", &make_lever},
        {"switch", &make_knob},
    };
    return table;
}

// The first object of `objects:` in a small YAML text, with positions, as the scene loader gives it.
struct Parsed {
    SceneDesc desc;
    const Node& first() const { return desc.root.find("objects")->items.at(0); }
};
Parsed parse(const std::string& yaml) {
    return {parse_scene_text(yaml, "t.yaml", ".")};
}

SceneError error_of(const std::function<void()>& action) {
    try {
        action();
    } catch (const SceneError& e) {
        return e;
    }
    ADD_FAILURE() << "no SceneError";
    return SceneError({}, "");
}

// The error's message and where it points.
void expect_error(const SceneError& e, const std::string& message, int line, int column) {
    EXPECT_EQ(e.message(), message);
    EXPECT_EQ(e.position().line, line) << message;
    EXPECT_EQ(e.position().column, column) << message;
}

TEST(NameTable, NamesAreInTableOrder) {
    EXPECT_EQ(widget_table().names(), (std::vector<std::string>{"knob", "lever", "switch"}));
    // The order a user sees in messages and --help is the order the table file lists.
    std::vector<std::string> listed;
    for (const WidgetEntry& entry : widget_table()) {
        listed.push_back(entry.name);
    }
    EXPECT_EQ(listed, widget_table().names());
    EXPECT_EQ(widget_table().size(), 3u);
    EXPECT_EQ(widget_table().front().name, "knob");
}

TEST(NameTable, FindGivesTheRowOrNull) {
    ASSERT_NE(widget_table().find("lever"), nullptr);
    EXPECT_EQ(widget_table().find("lever")->create, &make_lever);
    EXPECT_EQ(widget_table().find("leve"), nullptr);
    EXPECT_EQ(widget_table().find(""), nullptr);
    EXPECT_EQ(widget_table().find("Lever"), nullptr);  // names are case-sensitive, as scene keys are
}

TEST(NameTable, UnknownTypeIsReportedAtTheWordWithADidYouMean) {
    const Parsed parsed = parse("objects:\n  - size: 2\n    type: levr\n");
    Params params(parsed.first(), "objects[0]");
    const SceneError e = error_of([&] { widget_table().lookup_type(params, "widget"); });
    expect_error(e, "unknown widget type 'levr'; did you mean 'lever'? (known: knob, lever, switch)", 3, 11);
}

TEST(NameTable, NoSuggestionWhenNothingIsClose) {
    const Parsed parsed = parse("objects: [{type: teapot}]\n");
    Params params(parsed.first(), "objects[0]");
    const SceneError e = error_of([&] { widget_table().lookup(params, "type", "gadget"); });
    EXPECT_EQ(e.message(), "unknown gadget 'teapot' (known: knob, lever, switch)");
    EXPECT_EQ(e.position().column, 18);
}

TEST(NameTable, LookupOfANameFromElsewhereIsReportedWhereGiven) {
    const SourcePos command_line{SourceFile::from_text("command line", ""), 0, 0};
    EXPECT_EQ(&widget_table().lookup("switch", "widget", command_line), widget_table().find("switch"));
    const SceneError e = error_of([&] { widget_table().lookup("swich", "widget", command_line); });
    EXPECT_EQ(e.message(), "unknown widget 'swich'; did you mean 'switch'? (known: knob, lever, switch)");
    EXPECT_EQ(e.position().file->path, "command line");
}

TEST(NameTable, AMissingTypeIsReportedAsAMissingKey) {
    const Parsed parsed = parse("objects: [{size: 1}]\n");
    Params params(parsed.first(), "objects[0]");
    const SceneError e = error_of([&] { widget_table().lookup_type(params, "widget"); });
    EXPECT_EQ(e.message(), "objects[0] needs 'type'");
}

TEST(NameTable, ATableListingANameTwiceIsRefused) {
    const auto make = [] { return NameTable<WidgetEntry>{{"knob", &make_knob}, {"knob", &make_lever}}; };
    EXPECT_THROW(make(), std::logic_error);
}

TEST(NameTable, EveryConceptTableHasDistinctNames) {
    // Each table refuses a name listed twice when it is first built: building them all is the check.
    EXPECT_GT(shape_table().size(), 0u);
    EXPECT_GT(material_table().size(), 0u);
    EXPECT_GT(light_table().size(), 0u);
    EXPECT_GT(texture_table().size(), 0u);
    EXPECT_GT(camera_table().size(), 0u);
    EXPECT_GT(sampler_table().size(), 0u);
    EXPECT_GT(integrator_table().size(), 0u);
    EXPECT_GT(accelerator_table().size(), 0u);
    EXPECT_EQ(camera_table().front().name, "pinhole");  // the camera of a scene that names no type
}

TEST(BuildObject, LooksUpCreatesWithTheExtraArgumentsAndFinishes) {
    const Parsed parsed = parse("objects: [{type: lever, size: 3}]\n");
    const std::unique_ptr<Widget> widget = build_object(widget_table(), parsed.first(), "lever", "widget", 7);
    EXPECT_EQ(widget->kind, "lever");
    EXPECT_EQ(widget->size, 3);
    EXPECT_EQ(widget->extra, 7);
}

TEST(BuildObject, AKeyNobodyReadIsAnError) {
    const Parsed parsed = parse("objects:\n  - {type: knob, sise: 3}\n");
    const SceneError e =
        error_of([&] { build_object(widget_table(), parsed.first(), "objects[0]", "widget", 0); });
    expect_error(e, "unknown key 'sise' in objects[0]; did you mean 'size'? (expected one of: size, type)", 2,
                 18);
}

TEST(BuildObject, KeysReadBeforehandCount) {
    const Parsed parsed = parse("objects: [{type: knob, size: 3, colour: red}]\n");
    Params params(parsed.first(), "knob");
    params.string("colour");  // the caller's own key: read before the build step finishes
    EXPECT_EQ(build_object(widget_table(), params, "widget", 0)->size, 3);
}

TEST(BuildObject, AnUnknownTypeIsReportedBeforeCreateRuns) {
    const Parsed parsed = parse("objects: [{type: nob, size: -1}]\n");
    const SceneError e = error_of([&] { build_object(widget_table(), parsed.first(), "knob", "widget", 0); });
    EXPECT_EQ(e.message(), "unknown widget type 'nob'; did you mean 'knob'? (known: knob, lever, switch)");
}

enum class Wrap { Repeat, Clamp, Mirror };

const EnumTable<Wrap>& wrap_modes() {
    static const EnumTable<Wrap> table = {
        {"repeat", Wrap::Repeat},
        {"clamp", Wrap::Clamp},
        {"mirror", Wrap::Mirror},
        {"tile", Wrap::Repeat},  // an alias: read, never written
    };
    return table;
}

TEST(EnumTable, NamesAndValuesRoundTrip) {
    for (const Wrap wrap : {Wrap::Repeat, Wrap::Clamp, Wrap::Mirror}) {
        const std::string& name = wrap_modes().name_of(wrap);
        ASSERT_NE(wrap_modes().find(name), nullptr) << name;
        EXPECT_EQ(wrap_modes().find(name)->value, wrap) << name;
    }
    EXPECT_EQ(wrap_modes().name_of(Wrap::Clamp), "clamp");
    EXPECT_EQ(wrap_modes().name_of(Wrap::Repeat), "repeat");  // the first name, not the alias
    EXPECT_EQ(wrap_modes().find("tile")->value, Wrap::Repeat);
    EXPECT_EQ(wrap_modes().names(), (std::vector<std::string>{"repeat", "clamp", "mirror", "tile"}));
}

TEST(EnumTable, AValueWithoutANameIsAProgrammingError) {
    const EnumTable<Wrap> partial = {{"repeat", Wrap::Repeat}};
    EXPECT_THROW(partial.name_of(Wrap::Mirror), std::logic_error);
}

TEST(EnumTable, ParamsReadsAnEnumByItsTable) {
    const Parsed parsed = parse("objects: [{wrap: mirror}]\n");
    Params params(parsed.first(), "image");
    EXPECT_EQ(params.enumeration("wrap", wrap_modes(), Wrap::Clamp), Wrap::Mirror);
    EXPECT_EQ(params.enumeration("filter", wrap_modes(), Wrap::Clamp), Wrap::Clamp);  // absent: default
    EXPECT_NO_THROW(params.finish());                                                 // `wrap` was read
}

TEST(EnumTable, AnUnknownWordIsReportedAtItWithADidYouMean) {
    const Parsed parsed = parse("objects:\n  - {wrap: clmap}\n");
    Params params(parsed.first(), "image");
    const SceneError e = error_of([&] { params.enumeration("wrap", wrap_modes(), Wrap::Repeat); });
    expect_error(
        e, "image.wrap is 'clmap'; did you mean 'clamp'? (expected one of: repeat, clamp, mirror, tile)", 2,
        12);
}

TEST(EnumTable, ARequiredEnumMustBePresent) {
    const Parsed parsed = parse("objects: [{size: 1}]\n");
    Params params(parsed.first(), "image");
    const SceneError e = error_of([&] { params.enumeration("wrap", wrap_modes()); });
    EXPECT_EQ(e.message(), "image needs 'wrap'");
}

// The words of the scene format read through tables: each misspelling is reported where it stands,
// with the words the format accepts.
struct Misspelling {
    const char* yaml;
    const char* message;
    int line;
    int column;
};

TEST(SceneWords, EachMisspellingIsReportedAtItWithTheKnownWords) {
    const Misspelling cases[] = {
        {"materials:\n  m: {type: matte, albedo: {type: checker, space: sold}}\n",
         "material 'm'.albedo.space is 'sold'; did you mean 'solid'? (expected one of: uv, solid)", 2, 51},
        {"materials:\n  glass: {type: dielectric, fresnel: schlik}\n",
         "material 'glass'.fresnel is 'schlik'; did you mean 'schlick'? (expected one of: exact, schlick, "
         "schlick-outside)",
         2, 38},
        {"lights: [{type: environment, radiance: {type: gradiant}}]\n",
         "environment light.radiance.type is 'gradiant'; did you mean 'gradient'? (expected one of: "
         "gradient)",
         1, 47},
        // A texture inside a material: built by the generic build step in texture_table.cpp.
        {"materials:\n  m: {type: matte, albedo: {type: checkr}}\n",
         "unknown texture type 'checkr'; did you mean 'checker'? (known: constant, checker, image, noise)", 2,
         35},
    };
    for (const Misspelling& c : cases) {
        const SceneError e = error_of([&] { build_scene(parse_scene_text(c.yaml, "t.yaml", ".")); });
        expect_error(e, c.message, c.line, c.column);
    }
}

}  // namespace
}  // namespace glint
