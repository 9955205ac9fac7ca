// Edits of the scene's lists from the page: an object's inline material and a light, named by their
// position (objects.<i>.material.<key>, lights.<i>.<key>). The edited values reach the render as the
// formulas say (a matte albedo scales the pixel; a light's intensity scales what it alone lights), and
// anything else in the lists, or a bad value, is refused with its reason.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "generated_meshes.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/serve/preview_session.hpp"
#include "glint/serve/scene_edit.hpp"
#include "serve/open_watch.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

// A floor with an inline matte material under a point light 2 above its centre, seen from straight
// above; a named material and an object without one beside it, out of the picture.
const char* const kInlineScene = R"(
render: {width: 9, height: 9, samples: 4, sampler: jittered, integrator: raycast, seed: 1}
camera: {eye: [0, 4, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 10}
materials:
  grey: {type: matte, albedo: 0.5}
objects:
  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, albedo: [0.6, 0.4, 0.2]}}
  - {type: sphere, center: [5, 0, 5], radius: 0.5, material: grey}
  - {type: sphere, center: [-5, 0, 5], radius: 0.5}
lights:
  - {type: point, position: [0, 2, 0], intensity: 8}
)";

SceneDesc inline_scene() {
    return parse_scene_text(kInlineScene, "inline.yaml", ".");
}

// The message of the EditError `body` is refused with, or "" when it is accepted (or fails otherwise).
std::string edit_refusal(const SceneDesc& scene, const std::string& body) {
    try {
        apply_edit_request(scene, body);
    } catch (const EditError& e) {
        return e.what();
    } catch (const std::exception&) {
    }
    return "";
}

Film render_edited(const SceneDesc& scene, const std::string& body) {
    return test::render_film(build_scene(apply_edit_request(scene, body).desc));
}

TEST(SceneEditLists, InlineMaterialsAndLightsAreNamedByTheirPosition) {
    const SceneDesc loaded = inline_scene();
    // A position as a JSON number or as its digits.
    const EditedScene edited = apply_edit_request(loaded, R"({"edits": [
        {"path": ["objects", 0, "material", "albedo"], "value": [0.3, 0.4, 0.1]},
        {"path": ["objects", "0", "material", "type"], "value": "matte"},
        {"path": ["lights", 0, "intensity"], "value": [16, 8, 4]},
        {"path": ["lights", "0", "scale"], "value": 0.5}]})");
    const Node& object = edited.desc.root.find("objects")->items[0];
    EXPECT_EQ(node_to_json(*object.find("material")).dump(), R"({"type":"matte","albedo":[0.3,0.4,0.1]})");
    EXPECT_EQ(object.find("type")->scalar, "plane");
    const Node& light = edited.desc.root.find("lights")->items[0];
    EXPECT_EQ(node_to_json(light).dump(),
              R"({"type":"point","position":[0,2,0],"intensity":[16,8,4],"scale":0.5})");
    // A key removed again.
    const EditedScene removed =
        apply_edit_request(edited.desc, R"({"path": ["lights", 0, "scale"], "value": null})");
    EXPECT_EQ(removed.desc.root.find("lights")->items[0].find("scale"), nullptr);
}

TEST(SceneEditLists, WhatIsNotAnInlineMaterialOrALightIsRefusedWithItsReason) {
    const SceneDesc loaded = inline_scene();
    const auto refused = [&](const std::string& body) { return edit_refusal(loaded, body); };
    // An object's shape, place or the material key itself.
    EXPECT_NE(refused(R"({"path": ["objects", 0, "point"], "value": [0, 1, 0]})").find("inline material"),
              std::string::npos);
    EXPECT_NE(refused(R"({"path": ["objects", 0, "material"], "value": "grey"})").find("inline material"),
              std::string::npos);
    EXPECT_NE(refused(R"({"path": ["objects", "first", "material", "albedo"], "value": 1})")
                  .find("objects.<index>.material.<parameter>"),
              std::string::npos);
    // Positions that are not there: the message says how many there are.
    EXPECT_NE(refused(R"({"path": ["objects", 3, "material", "albedo"], "value": 0.5})")
                  .find("there is no object 3 in the scene; it has 3 objects"),
              std::string::npos);
    EXPECT_NE(refused(R"({"path": ["lights", 1, "intensity"], "value": 5})")
                  .find("there is no light 1 in the scene; it has 1 light"),
              std::string::npos);
    EXPECT_NE(refused(R"({"path": ["lights", -1, "intensity"], "value": 5})"), "");
    EXPECT_NE(refused(R"({"path": ["lights", 0], "value": 5})").find("lights.<index>.<parameter>"),
              std::string::npos);
    // A named material is edited under materials; an object without a material has none to edit.
    EXPECT_NE(refused(R"({"path": ["objects", 1, "material", "albedo"], "value": 0.3})")
                  .find("uses the named material 'grey': edit it as materials.grey.albedo"),
              std::string::npos);
    EXPECT_NE(refused(R"({"path": ["objects", 1, "material", "albedo", "scale"], "value": 2})")
                  .find("edit it as materials.grey.albedo.scale"),
              std::string::npos);
    EXPECT_NE(refused(R"({"path": ["objects", 2, "material", "albedo"], "value": 0.3})")
                  .find("has no material of its own"),
              std::string::npos);
    // A scene without lights has none to edit (and gets none made).
    const SceneDesc dark = parse_scene_text("objects: [{type: sphere, radius: 1}]\n", "dark.yaml", ".");
    EXPECT_NE(edit_refusal(dark, R"({"path": ["lights", 0, "intensity"], "value": 5})")
                  .find("the scene has no lights"),
              std::string::npos);
    // apply_edits alone (without parse_edits' checks) sets no key on a list either.
    Node root = loaded.root;
    Node value;
    value.kind = Node::Kind::Scalar;
    value.scalar = "1";
    EXPECT_THROW(apply_edits(root, {SceneEdit{{"lights", "0"}, value}}), EditError);
    // What is allowed is accepted.
    EXPECT_EQ(refused(R"({"path": ["objects", 0, "material", "albedo"], "value": 0.5})"), "");
    EXPECT_EQ(refused(R"({"path": ["lights", 0, "position"], "value": [0, 3, 0]})"), "");
}

// Values are checked by the constructors that read scene files, with their messages, at the value's
// line of the edited YAML.
TEST(SceneEditLists, BadValuesAreRefusedByTheSceneBuildersOwnChecks) {
    const SceneDesc loaded = inline_scene();
    const auto build_error = [&](const std::string& body) -> std::string {
        try {
            build_scene(apply_edit_request(loaded, body).desc);
        } catch (const SceneError& e) {
            EXPECT_EQ(e.position().file->path, "<scene in the browser>");
            return e.message();
        }
        return "built";
    };
    EXPECT_NE(build_error(R"({"path": ["lights", 0, "intensity"], "value": -3})").find("intensity"),
              std::string::npos);
    EXPECT_NE(build_error(R"({"path": ["lights", 0, "position"], "value": [1, 2]})").find("position"),
              std::string::npos);
    EXPECT_NE(
        build_error(R"({"path": ["lights", 0, "type"], "value": "pointy"})").find("did you mean 'point'"),
        std::string::npos);
    EXPECT_NE(
        build_error(R"({"path": ["objects", 0, "material", "albedo"], "value": "bright"})").find("albedo"),
        std::string::npos);
    EXPECT_NE(build_error(R"({"path": ["objects", 0, "material", "albdo"], "value": 0.5})")
                  .find("did you mean 'albedo'"),
              std::string::npos);
    EXPECT_EQ(build_error(R"({"path": ["objects", 0, "material", "albedo"], "value": 0.5})"), "built");
}

// Under the raycast integrator a matte floor lit by a point light a height h straight above shows
// L = ρ/π · I/h² there: linear in the albedo ρ, channel by channel.
TEST(SceneEditLists, AnInlineMatteAlbedoEditScalesThePixelAsTheFormulaSays) {
    const SceneDesc loaded = inline_scene();
    const Film before = test::render_film(build_scene(loaded));
    const Film after =
        render_edited(loaded, R"({"path": ["objects", 0, "material", "albedo"], "value": [0.3, 0.4, 0.1]})");
    const Rgb centre_before = before.pixel(4, 4);
    const Rgb centre_after = after.pixel(4, 4);
    // The value itself: ρ/π · 8/2², within the spread of the pixel's samples over the floor (~0.3%).
    const double lit = 8.0 / 4.0 / std::numbers::pi;
    EXPECT_NEAR(centre_before.r, 0.6 * lit, 0.6 * lit * 3e-3);
    EXPECT_NEAR(centre_after.r, 0.3 * lit, 0.3 * lit * 3e-3);
    // The ratio: exact, since the samples are the same and halving is exact in binary.
    for (int y = 0; y < before.height(); ++y) {
        for (int x = 0; x < before.width(); ++x) {
            const Rgb a = before.pixel(x, y), b = after.pixel(x, y);
            ASSERT_GT(a.r, 0) << x << "," << y;
            EXPECT_EQ(b.r, 0.5 * a.r) << x << "," << y;
            EXPECT_EQ(b.g, a.g) << x << "," << y;
            EXPECT_EQ(b.b, 0.5 * a.b) << x << "," << y;
        }
    }
}

// Two spot lights with disjoint pools of light on a matte floor. Doubling the first's intensity doubles
// every pixel only it lights and leaves every pixel only the second lights as it was.
TEST(SceneEditLists, DoublingALightsIntensityDoublesWhatItAloneLights) {
    const SceneDesc loaded = parse_scene_text(R"(
render: {width: 32, height: 16, samples: 4, sampler: jittered, integrator: raycast, seed: 3}
camera: {eye: [0, 6, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 40}
objects:
  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, albedo: 0.5}}
lights:
  - {type: spot, position: [-1.5, 2, 0], direction: [0, -1, 0], intensity: 10, angle: 15}
  - {type: spot, position: [1.5, 2, 0], direction: [0, -1, 0], intensity: 10, angle: 15}
)",
                                              "spots.yaml", ".");
    const Film both = test::render_film(build_scene(loaded));
    const Film doubled = render_edited(loaded, R"({"path": ["lights", 0, "intensity"], "value": 20})");
    // Each light alone, to know which pixels it lights.
    const Film first_only = render_edited(loaded, R"({"path": ["lights", 1, "scale"], "value": 0})");
    const Film second_only = render_edited(loaded, R"({"path": ["lights", 0, "scale"], "value": 0})");
    int only_first = 0, only_second = 0;
    for (int y = 0; y < both.height(); ++y) {
        for (int x = 0; x < both.width(); ++x) {
            const double first = first_only.pixel(x, y).r, second = second_only.pixel(x, y).r;
            if (first > 0 && second == 0) {
                ++only_first;
                EXPECT_EQ(doubled.pixel(x, y).r, 2 * both.pixel(x, y).r) << x << "," << y;
            } else if (second > 0 && first == 0) {
                ++only_second;
                EXPECT_EQ(doubled.pixel(x, y).r, both.pixel(x, y).r) << x << "," << y;
            }
        }
    }
    // Each pool covers a few pixels (a cone of 15° from 2 above: a disc of radius 0.54 on the floor).
    EXPECT_GT(only_first, 4);
    EXPECT_GT(only_second, 4);
}

// In the preview, an inline material edit rebuilds the material only: the mesh is not read again and
// its BVH not rebuilt, as for a named material (preview_session_test.cpp).
TEST(SceneEditLists, AnInlineMaterialEditInThePreviewKeepsTheMeshAndReadsNoFile) {
    test::TempDir dir;
    test::write_binary_ply(test::displaced_torus(64, 32), dir / "torus.ply");
    const std::string text =
        "render: {width: 16, height: 12, samples: 2}\n"
        "camera: {eye: [0, 2, 3], look_at: [0, 0, 0], fov: 50}\n"
        "objects: [{type: mesh, file: torus.ply, material: {type: matte, albedo: [0.7, 0.6, 0.5]}}]\n"
        "lights: [{type: point, position: [2, 4, 2], intensity: 20}]\n";
    PreviewSession session(parse_scene_text(text, (dir / "scene.yaml").string(), dir.path()), "scene.yaml");
    const std::shared_ptr<const World> before = session.world();
    test::OpenWatch watch(dir.path());
    EXPECT_EQ(session.apply_request(R"({"path": ["objects", 0, "material", "albedo"], "value": 0.25})"), 2u);
    EXPECT_EQ(session.apply_request(R"({"path": ["lights", 0, "intensity"], "value": 40})"), 3u);
    const std::shared_ptr<const World> after = session.world();
    ASSERT_EQ(after->shapes.size(), 1u);
    EXPECT_EQ(after->shapes[0], before->shapes[0]);
    EXPECT_EQ(after->accelerator, before->accelerator);
    EXPECT_NE(after->materials[after->shape_materials[0]].get(),
              before->materials[before->shape_materials[0]].get());
    EXPECT_EQ(watch.opened(), std::vector<std::string>{});
    EXPECT_NE(session.state().yaml.find("albedo: 0.25"), std::string::npos) << session.state().yaml;
    session.stop();
}

}  // namespace
}  // namespace glint
