// glTF's metallic-roughness material with its textures, and what they need in glint: image textures that
// read one channel, scaled and linear (texture/image_texture.cpp), and tangent-space normal maps on
// meshes (geometry/mesh.cpp, `normal_map`). Each render is checked against a value known without the
// code: Lambert's cosine law under a directional light, or the same material with constant parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "glint/image/image_io.hpp"
#include "glint/import/importer.hpp"
#include "glint/scene/scene_writer.hpp"
#include "glint/texture/image_texture.hpp"
#include "gltf_test_util.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

using nlohmann::json;

// A PFM of colours.size() × 1 texels, texel i coloured colours[i] (linear, exact up to float).
std::string write_pfm(test::TempDir& dir, const std::string& name, const std::vector<Rgb>& colours) {
    Image image(static_cast<int>(colours.size()), 1);
    for (std::size_t i = 0; i < colours.size(); ++i) {
        image.rgb[3 * i] = static_cast<float>(colours[i].r);
        image.rgb[3 * i + 1] = static_cast<float>(colours[i].g);
        image.rgb[3 * i + 2] = static_cast<float>(colours[i].b);
    }
    const std::vector<unsigned char> bytes = encode_pfm(image);
    dir.write(name, std::string(bytes.begin(), bytes.end()));
    return (dir / name).string();
}

std::string yaml_vec(const Vec3& v) {
    char text[128];
    std::snprintf(text, sizeof text, "[%.17g, %.17g, %.17g]", v.x, v.y, v.z);
    return text;
}

// A camera looking straight down at the unit square [0, 1]² in z = 0, whose uvs are u = x, v = y and
// whose normals are +z, lit by a directional light of irradiance 1 travelling along `light`.
// `normal_map` and `material` are YAML (normal_map empty for none). Raycast, one sample at each pixel
// centre, 16 × 16 pixels all on the square.
Film render_square(const std::string& normal_map, const std::string& material, const Vec3& light,
                   const std::string& extra_mesh_keys = "") {
    std::string scene =
        "render: {width: 16, height: 16, samples: 1, sampler: regular}\n"
        "camera: {type: orthographic, eye: [0.5, 0.5, 1], look_at: [0.5, 0.5, 0], up: [0, 1, 0], height: 1}\n"
        "lights:\n  - {type: directional, irradiance: 1, direction: " +
        yaml_vec(light) +
        "}\n"
        "objects:\n"
        "  - type: mesh\n"
        "    positions: [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0]\n"
        "    indices: [0, 1, 2, 0, 2, 3]\n"
        "    normals: [0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]\n"
        "    uvs: [0, 0, 1, 0, 1, 1, 0, 1]\n"
        "    material: " +
        material + "\n" + extra_mesh_keys;
    if (!normal_map.empty()) {
        scene += "    normal_map: " + normal_map + "\n";
    }
    return test::render_film(test::scene_from_text(scene));
}

constexpr const char* kWhiteMatte = "{type: matte, albedo: 1}";

// The texel of a normal map that holds the tangent-space normal n (unit): (n + 1) / 2.
Rgb encoded(const Vec3& n) {
    return {(n.x + 1) / 2, (n.y + 1) / 2, (n.z + 1) / 2};
}

TEST(NormalMap, AFlatMapGivesTheSameBitsAsNoMap) {
    test::TempDir dir;
    const std::string flat = write_pfm(dir, "flat.pfm", {{0.5, 0.5, 1}});
    const Vec3 light = normalize(Vec3{0.3, -0.2, -1});
    const Film without = render_square("", kWhiteMatte, light);
    const Film with = render_square("{file: '" + flat + "', scale: 2}", kWhiteMatte, light);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            ASSERT_EQ(with.pixel(x, y).r, without.pixel(x, y).r) << x << ", " << y;
        }
    }
    EXPECT_GT(without.pixel(8, 8).r, 0.1);
}

TEST(NormalMap, ATiltByAnAngleScalesLambertShadingByItsCosine) {
    // Light straight down: without a map a white matte square shows 1/π. A map tilting the normal by
    // 60° (in either tangent direction) halves it, cos 60° = ½, whichever way it tilts.
    test::TempDir dir;
    const double angle = kPi / 3;
    const std::string along_u = write_pfm(dir, "u.pfm", {encoded({std::sin(angle), 0, std::cos(angle)})});
    const std::string along_v = write_pfm(dir, "v.pfm", {encoded({0, std::sin(angle), std::cos(angle)})});
    const Vec3 down{0, 0, -1};
    const Film flat = render_square("", kWhiteMatte, down);
    const Film tilted_u = render_square("{file: '" + along_u + "'}", kWhiteMatte, down);
    const Film tilted_v = render_square("{file: '" + along_v + "'}", kWhiteMatte, down);
    EXPECT_NEAR(flat.pixel(5, 9).r, 1 / kPi, 1e-12);
    EXPECT_NEAR(tilted_u.pixel(5, 9).r, std::cos(angle) / kPi, 1e-6);
    EXPECT_NEAR(tilted_v.pixel(5, 9).r, std::cos(angle) / kPi, 1e-6);
}

TEST(NormalMap, RedTiltsTowardsUAndGreenTowardsV) {
    // The same 60° tilts, now lit from the direction the tilted normal points to (+u = +x for red,
    // +v = +y for green): the light meets the mapped normal head on, 1/π, where the unmapped square
    // shows cos 60°/π. A map tilting the wrong way would show cos 120° < 0: black.
    test::TempDir dir;
    const double angle = kPi / 3;
    const Vec3 towards_x{std::sin(angle), 0, std::cos(angle)}, towards_y{0, std::sin(angle), std::cos(angle)};
    const std::string red = write_pfm(dir, "u.pfm", {encoded(towards_x)});
    const std::string green = write_pfm(dir, "v.pfm", {encoded(towards_y)});
    EXPECT_NEAR(render_square("", kWhiteMatte, -towards_x).pixel(5, 9).r, std::cos(angle) / kPi, 1e-12);
    EXPECT_NEAR(render_square("{file: '" + red + "'}", kWhiteMatte, -towards_x).pixel(5, 9).r, 1 / kPi, 1e-6);
    EXPECT_NEAR(render_square("{file: '" + green + "'}", kWhiteMatte, -towards_y).pixel(5, 9).r, 1 / kPi,
                1e-6);
    // scale multiplies x and y: the red map at scale 0 is flat again.
    EXPECT_NEAR(render_square("{file: '" + red + "', scale: 0}", kWhiteMatte, -towards_x).pixel(5, 9).r,
                std::cos(angle) / kPi, 1e-6);
}

TEST(NormalMap, AMeshWithoutUvsOrAMisspeltKeyIsAnError) {
    test::TempDir dir;
    const std::string flat = write_pfm(dir, "flat.pfm", {{0.5, 0.5, 1}});
    const std::string header =
        "objects:\n  - {type: mesh, positions: [0, 0, 0, 1, 0, 0, 0, 1, 0], indices: [0, 1, 2], ";
    try {
        test::scene_from_text(header + "normal_map: {file: '" + flat + "'}}\n");
        FAIL() << "a normal map without uvs was accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("texture coordinates"), std::string::npos) << e.what();
    }
    try {
        test::scene_from_text(header + "uvs: [0, 0, 1, 0, 0, 1], normal_map: {file: '" + flat +
                              "', scael: 1}}\n");
        FAIL() << "a misspelt key was accepted";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("scale"), std::string::npos) << e.what();
    }
}

TEST(ImageTexture, AChannelScaleAndEncodingAreAppliedToEveryTexel) {
    Image image(2, 1);
    image.rgb = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f};
    const ImageTexture blue(image, ImageTexture::Channel::B, Rgb(0.5));
    EXPECT_NEAR(blue.lookup({0.25, 0.5}).r, 0.15, 1e-7);
    EXPECT_NEAR(blue.lookup({0.25, 0.5}).g, 0.15, 1e-7);
    EXPECT_NEAR(blue.lookup({0.75, 0.5}).b, 0.3, 1e-7);
    EXPECT_NEAR(blue.min_value(), 0.15, 1e-7);
    EXPECT_NEAR(blue.max_value(), 0.3, 1e-7);
    const ImageTexture green(image, ImageTexture::Channel::G, Rgb(1, 2, 0));
    const Rgb at = green.lookup({0.75, 0.5});
    EXPECT_NEAR(at.r, 0.5, 1e-7);
    EXPECT_NEAR(at.g, 1.0, 1e-7);
    EXPECT_EQ(at.b, 0.0);

    // An 8-bit PNG whose texels are the bytes 200 and 51: sRGB-decoded by default, as they are with
    // `encoding: linear` (200/255, 51/255).
    Image bytes(2, 1);
    for (int c = 0; c < 3; ++c) {
        bytes.rgb[static_cast<std::size_t>(c)] = static_cast<float>(srgb_to_linear(200 / 255.0));
        bytes.rgb[static_cast<std::size_t>(3 + c)] = static_cast<float>(srgb_to_linear(51 / 255.0));
    }
    test::TempDir dir;
    const std::vector<unsigned char> png = encode_png(bytes);
    dir.write("bytes.png", std::string(png.begin(), png.end()));
    EXPECT_NEAR(read_image(dir / "bytes.png").rgb[0], srgb_to_linear(200 / 255.0), 1e-6);
    EXPECT_NEAR(read_image(dir / "bytes.png", false).rgb[0], 200 / 255.0, 1e-7);
    EXPECT_NEAR(read_image(dir / "bytes.png", false).rgb[3], 51 / 255.0, 1e-7);
}

// The square with principled metallic from a texture, against the same square with a constant metallic.
TEST(Principled, AMetallicMapsBlueChannelGivesMetalWhereItIsOneAndDielectricWhereItIsZero) {
    // An 8 × 1 map, blue 1 in its left half and 0 in its right (red and green other values, to show
    // they are not read). Away from the middle and the wrap-around the lookup is 1 or 0.
    test::TempDir dir;
    std::vector<Rgb> texels;
    for (int i = 0; i < 8; ++i) {
        texels.push_back(i < 4 ? Rgb(0.3, 0.7, 1) : Rgb(0.9, 0.2, 0));
    }
    const std::string map = write_pfm(dir, "mr.pfm", texels);
    const auto principled = [](const std::string& metallic, const std::string& roughness) {
        return "{type: principled, base_color: [0.9, 0.6, 0.3], metallic: " + metallic +
               ", roughness: " + roughness + "}";
    };
    const Vec3 light = normalize(Vec3{0.2, 0.1, -1});
    const Film textured =
        render_square("", principled("{type: image, file: '" + map + "', channel: b}", "0.5"), light);
    const Film metal = render_square("", principled("1", "0.5"), light);
    const Film dielectric = render_square("", principled("0", "0.5"), light);
    ASSERT_GT(std::abs(metal.pixel(3, 8).r - dielectric.pixel(3, 8).r),
              0.01);  // the test can tell them apart
    for (int y = 0; y < 16; ++y) {
        for (int x : {2, 3, 4, 5}) {  // u in (0.125, 0.375)
            EXPECT_NEAR(textured.pixel(x, y).r, metal.pixel(x, y).r, 1e-9) << x << ", " << y;
            EXPECT_NEAR(textured.pixel(x, y).b, metal.pixel(x, y).b, 1e-9) << x << ", " << y;
        }
        for (int x : {10, 11, 12, 13}) {  // u in (0.625, 0.875)
            EXPECT_NEAR(textured.pixel(x, y).r, dielectric.pixel(x, y).r, 1e-9) << x << ", " << y;
            EXPECT_NEAR(textured.pixel(x, y).b, dielectric.pixel(x, y).b, 1e-9) << x << ", " << y;
        }
    }
    // Roughness from the green channel (0.7 left, 0.2 right) times a factor ½: 0.35 and 0.1.
    const Film rough = render_square(
        "", principled("0", "{type: image, file: '" + map + "', channel: g, scale: 0.5}"), light);
    const Film left = render_square("", principled("0", "0.35"), light);
    const Film right = render_square("", principled("0", "0.1"), light);
    EXPECT_NEAR(rough.pixel(3, 8).g, left.pixel(3, 8).g, 1e-6);
    EXPECT_NEAR(rough.pixel(12, 8).g, right.pixel(12, 8).g, 1e-6);
    EXPECT_GT(std::abs(left.pixel(3, 8).g - right.pixel(3, 8).g), 1e-3);
}

// A unit square with TEXCOORD_0 (u = x, v = y in glint's convention) and, when `tangents`, a TANGENT of
// (0, 1, 0, 1) at every vertex: tangents that say u runs along +y, not +x as the uvs do.
json textured_square(bool tangents) {
    const float positions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const float uvs[] = {0, 1, 1, 1, 1, 0, 0, 0};  // glTF's v runs down the image: v_glTF = 1 − y
    const float tangent[] = {0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1};
    const std::uint16_t indices[] = {0, 1, 2, 0, 2, 3};
    std::string bytes(sizeof positions + sizeof uvs + sizeof indices + sizeof tangent, '\0');
    std::memcpy(bytes.data(), positions, sizeof positions);
    std::memcpy(bytes.data() + 48, uvs, sizeof uvs);
    std::memcpy(bytes.data() + 80, tangent, sizeof tangent);
    std::memcpy(bytes.data() + 144, indices, sizeof indices);
    const std::string base64 = test::base64(bytes);
    json attributes = {{"POSITION", 0}, {"TEXCOORD_0", 1}};
    if (tangents) {
        attributes["TANGENT"] = 3;
    }
    return {{"asset", {{"version", "2.0"}}},
            {"scene", 0},
            {"scenes", {{{"nodes", {0}}}}},
            {"nodes", {{{"mesh", 0}}}},
            {"meshes", {{{"primitives", {{{"attributes", attributes}, {"indices", 2}, {"material", 0}}}}}}},
            {"materials",
             {{{"name", "textured"},
               {"pbrMetallicRoughness",
                {{"baseColorFactor", {0.5, 1, 1, 1}},
                 {"baseColorTexture", {{"index", 0}}},
                 {"metallicFactor", 0.25},
                 {"metallicRoughnessTexture", {{"index", 1}}}}},
               {"normalTexture", {{"index", 2}, {"scale", 0.8}}},
               {"occlusionTexture", {{"index", 1}}}}}},
            {"textures", {{{"source", 0}}, {{"source", 1}}, {{"source", 2}}}},
            {"images", {{{"uri", "base.pfm"}}, {{"uri", "mr.pfm"}}, {{"uri", "normal.pfm"}}}},
            {"buffers",
             {{{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + base64}}}},
            {"bufferViews",
             {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
              {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 32}},
              {{"buffer", 0}, {"byteOffset", 144}, {"byteLength", 12}},
              {{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 64}}}},
            {"accessors",
             {test::unit_square_positions_accessor(),
              {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
              {{"bufferView", 2}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}},
              {{"bufferView", 3}, {"componentType", 5126}, {"count", 4}, {"type", "VEC4"}}}}};
}

bool warned(const SceneDesc& desc, const std::string& text) {
    for (const SceneWarning& warning : desc.warnings) {
        if (warning.message.find(text) != std::string::npos) {
            return true;
        }
    }
    return false;
}

TEST(GltfImport, TheMetallicRoughnessNormalAndBaseColourMapsAreMappedWithTheirFactors) {
    test::TempDir dir;
    write_pfm(dir, "base.pfm", {{1, 1, 1}});
    write_pfm(dir, "mr.pfm", {{0, 0.5, 1}});
    write_pfm(dir, "normal.pfm", {encoded(normalize(Vec3{0.3, -0.2, 1}))});
    dir.write("square.gltf", textured_square(false).dump());
    const SceneDesc desc = load_scene(dir / "square.gltf");
    const Node& object = desc.root.find("objects")->items.at(0);
    EXPECT_EQ(write_scene_yaml(*object.find("material")),
              "type: principled\n\n"
              "base_color:\n  type: image\n  file: base.pfm\n  scale: [0.5, 1, 1]\n\n"
              "metallic:\n  type: image\n  file: mr.pfm\n  channel: b\n  encoding: linear\n  scale: 0.25\n\n"
              "roughness:\n  type: image\n  file: mr.pfm\n  channel: g\n  encoding: linear\n");
    EXPECT_EQ(write_scene_yaml(*object.find("normal_map")), "file: normal.pfm\n\nscale: 0.8\n");
    EXPECT_FALSE(warned(desc, "normal map")) << "the normal map is read";
    EXPECT_FALSE(warned(desc, "metallic-roughness")) << "the metallic-roughness map is read";
    EXPECT_TRUE(warned(desc, "occlusion map is ignored"));
    EXPECT_NO_THROW(build_scene(desc));
    // Converted to YAML (the maps' files rebased), it renders the same bits.
    test::expect_convert_round_trip(dir, "square.gltf");

    // A second texture coordinate set and a texture transform are said.
    json other = textured_square(false);
    other["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 1;
    other["materials"][0]["normalTexture"]["extensions"] = {{"KHR_texture_transform", {{"scale", {2, 2}}}}};
    dir.write("other.gltf", other.dump());
    const SceneDesc said = load_scene(dir / "other.gltf");
    EXPECT_TRUE(warned(said, "TEXCOORD_1"));
    EXPECT_TRUE(warned(said, "KHR_texture_transform"));
}

TEST(GltfImport, ANormalMapTurnsWithTheTangentsTheFileGives) {
    // A normal map tilting 60° towards +tangent, on the glTF square as a mesh. From the uvs the tangent
    // is +x; the file's TANGENT says +y. Lit along (0, sin 60°, cos 60°), a white matte square shows 1/π
    // with the file's tangents (the mapped normal is that direction), and with tangents from the uvs
    // (mapped normal (sin 60°, 0, cos 60°)) cos² 60°/π = ¼/π.
    test::TempDir dir;
    const double angle = kPi / 3;
    const std::string normal = write_pfm(dir, "normal.pfm", {encoded({std::sin(angle), 0, std::cos(angle)})});
    const auto shade = [&](bool tangents) {
        dir.write("square.gltf", textured_square(tangents).dump());
        const std::string yaml =
            "render: {width: 8, height: 8, samples: 1, sampler: regular}\n"
            "camera: {type: orthographic, eye: [0.5, 0.5, 1], look_at: [0.5, 0.5, 0], up: [0, 1, 0], "
            "height: 1}\n"
            "lights: [{type: directional, direction: " +
            yaml_vec(-Vec3{0, std::sin(angle), std::cos(angle)}) +
            "}]\n"
            "objects:\n"
            "  - {type: mesh, file: '" +
            (dir / "square.gltf").string() + "', gltf_mesh: 0, gltf_primitive: 0, normal_map: {file: '" +
            normal + "'}, material: {type: matte, albedo: 1}}\n";
        return test::render_film(test::scene_from_text(yaml)).pixel(3, 5).r;
    };
    EXPECT_NEAR(shade(true), 1 / kPi, 1e-6);
    EXPECT_NEAR(shade(false), std::cos(angle) * std::cos(angle) / kPi, 1e-6);
}

}  // namespace
}  // namespace glint