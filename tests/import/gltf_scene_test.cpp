// The glTF importer (src/glint/import/gltf_scene.cpp) and the glTF mesh reader
// (geometry/mesh_io/gltf_file.cpp) on models written here: a node hierarchy's world matrix, the
// camera, materials, KHR_lights_punctual, .glb, accessors that reach past their buffer, and
// `glint convert`'s round trip.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "glint/geometry/mesh.hpp"
#include "glint/geometry/mesh_io/gltf_file.hpp"
#include "glint/image/image_io.hpp"
#include "glint/import/importer.hpp"
#include "glint/scene/scene_writer.hpp"
#include "gltf_test_util.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

using nlohmann::json;

using test::square_bytes;

using test::base64;

// A model: the square under node 1, a child of node 0; `buffer_uri` empty for a .glb's own buffer.
json square_model(const std::string& buffer_uri) {
    json model = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes",
         {{{"translation", {0, 0, -3}},
           {"rotation", {0, 0.7071067811865476, 0, 0.7071067811865476}},
           {"children", {1}}},
          {{"mesh", 0}, {"scale", {2, 2, 2}}}}},
        {"meshes",
         {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"material", 0}}}}}}},
        {"materials",
         {{{"name", "red"},
           {"pbrMetallicRoughness",
            {{"baseColorFactor", {0.8, 0.1, 0.1, 1}}, {"metallicFactor", 0.25}, {"roughnessFactor", 0.5}}},
           {"normalTexture", {{"index", 0}}}}}},
        {"textures", {{{"source", 0}}}},
        {"images", {{{"uri", "normals.png"}}}},
        {"buffers", {{{"byteLength", 60}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
          {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 12}}}},
        {"accessors",
         {test::unit_square_positions_accessor(),
          {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}}};
    if (!buffer_uri.empty()) {
        model["buffers"][0]["uri"] = buffer_uri;
    }
    return model;
}

std::string data_uri() {
    return "data:application/octet-stream;base64," + base64(square_bytes());
}

std::string glb(const json& model, std::string binary) {
    return test::glb(model.dump(), std::move(binary));
}

// Where a ray along −x... finds the square: the scene's one object, hit from `origin` along `dir`.
bool hits(const Scene& scene, const Vec3& origin, const Vec3& dir, Hit& hit) {
    return scene.world->shapes.at(0)->intersect(Ray{origin, dir}, kInf, hit);
}

TEST(GltfImport, TheNodeHierarchyPlacesTheMesh) {
    // Node 1 scales the unit square by 2; node 0 turns it 90° about +y (x → −z) and moves it to
    // z = −3. The square's corners (0,0,0), (1,1,0) end at (0,0,−3) and (0,2,−5): it lies in the plane
    // x = 0, z from −3 to −5, y from 0 to 2.
    test::TempDir dir;
    dir.write("square.gltf", square_model(data_uri()).dump());
    const Scene scene = build_scene(load_scene(dir / "square.gltf"));
    Hit hit;
    ASSERT_TRUE(hits(scene, {5, 1, -4}, {-1, 0, 0}, hit));
    EXPECT_NEAR(hit.point.x, 0, 1e-9);
    EXPECT_NEAR(hit.t, 5, 1e-9);
    EXPECT_FALSE(hits(scene, {5, 1, -2.9}, {-1, 0, 0}, hit));  // beyond its edges
    EXPECT_FALSE(hits(scene, {5, 2.1, -4}, {-1, 0, 0}, hit));
}

TEST(GltfImport, MaterialsBecomePrincipledAndWhatIsLeftOutIsAWarning) {
    test::TempDir dir;
    dir.write("square.gltf", square_model(data_uri()).dump());
    const SceneDesc desc = load_scene(dir / "square.gltf");
    const Node& object = desc.root.find("objects")->items.at(0);
    EXPECT_EQ(write_scene_yaml(*object.find("material")),
              "type: principled\n\nbase_color: [0.8, 0.1, 0.1]\n\nmetallic: 0.25\n\nroughness: 0.5\n");
    bool normal_map_warned = false;
    for (const SceneWarning& warning : desc.warnings) {
        normal_map_warned = normal_map_warned ||
                            warning.message.find("has no TEXCOORD_0: the normal map") != std::string::npos;
    }
    EXPECT_TRUE(normal_map_warned) << "the square has no TEXCOORD_0 to map its normal map by";
}

TEST(GltfImport, TheCameraLooksDownItsNodesMinusZWithItsVerticalFov) {
    test::TempDir dir;
    json model = square_model(data_uri());
    model["cameras"] = {
        {{"name", "side"}, {"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}}};
    // A camera node turned 90° about +y: it looks along −x, from (4, 1, −4).
    model["nodes"].push_back({{"camera", 0},
                              {"translation", {4, 1, -4}},
                              {"rotation", {0, 0.7071067811865476, 0, 0.7071067811865476}}});
    model["scenes"][0]["nodes"].push_back(2);
    dir.write("camera.gltf", model.dump());
    const Scene scene = build_scene(load_scene(dir / "camera.gltf"));
    const SceneDesc desc = load_scene(dir / "camera.gltf");
    const Node& camera = *desc.root.find("camera");
    EXPECT_NEAR(std::stod(camera.find("fov")->scalar), 0.5 * 180 / kPi, 1e-12);
    EXPECT_NEAR(std::stod(camera.find("look_at")->items[0].scalar), 3, 1e-12);  // eye + (−1, 0, 0)
    EXPECT_NEAR(std::stod(camera.find("look_at")->items[2].scalar), -4, 1e-12);
    // --camera picks it by name; an unknown name is an error.
    ImportOptions options;
    options.camera = "nowhere";
    EXPECT_THROW(load_scene(dir / "camera.gltf", options), SceneError);
}

TEST(GltfImport, PunctualLightsKeepTheirColourTimesIntensity) {
    test::TempDir dir;
    json model = square_model(data_uri());
    model["extensionsUsed"] = {"KHR_lights_punctual"};
    model["extensions"] = {
        {"KHR_lights_punctual",
         {{"lights", {{{"type", "point"}, {"color", {1, 0.5, 0.25}}, {"intensity", 8}}}}}}};
    model["nodes"].push_back(
        {{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    model["scenes"][0]["nodes"].push_back(2);
    dir.write("light.gltf", model.dump());
    const SceneDesc desc = load_scene(dir / "light.gltf");
    ASSERT_NE(desc.root.find("lights"), nullptr);
    EXPECT_EQ(write_scene_yaml(desc.root.find("lights")->items.at(0)),
              "type: point\n\nposition: [1, 2, 3]\n\nintensity: [8, 4, 2]\n");
}

TEST(GltfImport, AGlbReadsLikeTheGltf) {
    test::TempDir dir;
    dir.write("square.gltf", square_model(data_uri()).dump());
    dir.write("square.glb", glb(square_model(""), square_bytes()));
    const MeshData a = gltf_primitive_mesh(*load_gltf_file(dir / "square.gltf", {}), 0, 0, {});
    const MeshData b = gltf_primitive_mesh(*load_gltf_file(dir / "square.glb", {}), 0, 0, {});
    EXPECT_EQ(a.positions.size(), 4u);
    EXPECT_EQ(a.triangles.size(), 2u);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.triangles, b.triangles);
}

TEST(GltfImport, AnAccessorReachingPastItsBufferIsAnError) {
    test::TempDir dir;
    json model = square_model(data_uri());
    model["accessors"][0]["count"] = 5;  // 5 × 12 bytes do not fit the view's 48
    dir.write("long.gltf", model.dump());
    try {
        build_scene(load_scene(dir / "long.gltf"));
        FAIL() << "an accessor past its buffer was read";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("POSITION accessor 0 (5 elements) reaches past its buffer"),
                  std::string::npos)
            << e.what();
    }
    const auto cli = test::run_glint("render '" + (dir / "long.gltf").string() + "' -o '" +
                                     (dir / "long.png").string() + "' -q");
    EXPECT_EQ(cli.exit_code, 2) << cli.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "long.png"));
    dir.write("broken.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"nodes\": [");
    const auto broken = test::run_glint("render '" + (dir / "broken.gltf").string() + "' -o '" +
                                        (dir / "broken.png").string() + "' -q");
    EXPECT_EQ(broken.exit_code, 2) << broken.output;
}

TEST(GltfImport, AnImageStoredInTheModelRendersAsTheSameImageInAFile) {
    // A 2 × 1 PFM (left 0.25, right 0.75) as the base colour map: once as a file beside the model,
    // once inside it as a data: URI. The two renders must be the same bits.
    Image texture(2, 1);
    texture.rgb = {0.25f, 0.25f, 0.25f, 0.75f, 0.75f, 0.75f};
    const std::vector<unsigned char> pfm = encode_pfm(texture);
    const std::string pfm_bytes(pfm.begin(), pfm.end());
    test::TempDir dir;
    dir.write("texture.pfm", pfm_bytes);
    json outside = square_model(data_uri());
    outside["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    outside["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {1, 1, 1, 1};
    outside["images"][0]["uri"] = "texture.pfm";
    json inside = outside;
    inside["images"][0]["uri"] = "data:application/octet-stream;base64," + base64(pfm_bytes);
    dir.write("outside.gltf", outside.dump());
    dir.write("inside.gltf", inside.dump());
    const SceneDesc inside_desc = load_scene(dir / "inside.gltf");
    const Node& base = *inside_desc.root.find("objects")->items.at(0).find("material")->find("base_color");
    EXPECT_EQ(write_scene_yaml(base), "type: image\n\nfile: inside.gltf\n\ngltf_image: 0\n");
    RenderFlags flags;
    flags.width = 16;
    flags.height = 8;
    flags.samples_per_pixel = 2;
    const Film a = test::render_film(build_scene(load_scene(dir / "outside.gltf"), flags));
    const Film b = test::render_film(build_scene(inside_desc, flags));
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 16; ++x) {
            ASSERT_EQ(a.pixel(x, y).r, b.pixel(x, y).r) << x << ", " << y;
        }
    }
    // A stored image that is not an image is an error at the texture, exit 2 from the CLI.
    inside["images"][0]["uri"] = "data:application/octet-stream;base64," + base64("not an image");
    dir.write("broken.gltf", inside.dump());
    EXPECT_THROW(build_scene(load_scene(dir / "broken.gltf")), SceneError);
}

TEST(GltfImport, ConvertWritesAYamlThatRendersTheSameBits) {
    test::TempDir dir;
    dir.write("square.gltf", square_model(data_uri()).dump());
    test::expect_convert_round_trip(dir, "square.gltf");
}

}  // namespace
}  // namespace glint
