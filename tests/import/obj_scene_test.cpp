// The OBJ importer (src/glint/import/obj_scene.cpp) and what it builds on: OBJ texture coordinates,
// meshes of one usemtl, inline meshes, MTL materials mapped to glint's, warnings at their statements,
// and `glint convert`, whose YAML renders the same bits.
#include <gtest/gtest.h>

#include <fstream>

#include "glint/geometry/mesh.hpp"
#include "glint/geometry/mesh_io/mesh_data.hpp"
#include "glint/image/image_io.hpp"
#include "glint/import/importer.hpp"
#include "glint/import/obj_scene.hpp"
#include "glint/scene/scene_writer.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

// A unit square in the z = 0 plane, facing +z, with texture coordinates running over it as x and y
// (and the square's own corner order reversed in vt, so barycentrics alone would not give them).
const char* kSquareObj =
    "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "f 1/1 2/2 3/3 4/4\n";

TEST(ObjTextureCoordinates, AreInterpolatedIntoTheHit) {
    test::TempDir dir;
    Mesh mesh(load_obj(dir.write("square.obj", kSquareObj)));
    for (const auto& [x, y] : {std::pair{0.5, 0.25}, {1.5, 0.75}, {1.9, 0.1}}) {
        Hit hit;
        ASSERT_TRUE(mesh.intersect(Ray{{x, y, 1}, {0, 0, -1}}, kInf, hit));
        const Point2 uv = surface_uv(hit);
        EXPECT_NEAR(uv.x, x / 2, 1e-12);
        EXPECT_NEAR(uv.y, y, 1e-12);
    }
}

TEST(ObjTextureCoordinates, CornersThatDifferOnlyInVtBecomeSeparateVertices) {
    test::TempDir dir;
    // Two triangles share positions 1 and 3 but give them other texture coordinates.
    const MeshData data = load_obj(dir.write("seam.obj",
                                             "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                             "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
                                             "f 1/1 2/2 3/3\nf 1/5 3/5 4/4\n"));
    EXPECT_EQ(data.positions.size(), 6u);
    ASSERT_EQ(data.uvs.size(), 6u);
    EXPECT_EQ(data.uvs[3], (Point2{0.5, 0.5}));
}

TEST(PlyTextureCoordinates, AreReadUnderEachOfTheirNames) {
    test::TempDir dir;
    for (const auto& [u, v] : {std::pair{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}}) {
        const std::string ply = std::string("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n") +
                                "property float y\nproperty float z\nproperty float " + u +
                                "\nproperty float " + v +
                                "\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n" +
                                "0 0 0 0.25 0.5\n1 0 0 1 0.5\n0 1 0 0.25 1\n3 0 1 2\n";
        const MeshData data = load_mesh_file(dir.write(std::string("uv-") + u + ".ply", ply));
        ASSERT_EQ(data.uvs.size(), 3u) << u;
        EXPECT_EQ(data.uvs[0], (Point2{0.25, 0.5})) << u;
        EXPECT_EQ(data.uvs[1], (Point2{1, 0.5})) << u;
    }
}

TEST(ObjTextureCoordinates, BadIndicesArePositionedErrors) {
    test::TempDir dir;
    try {
        load_obj(dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n"));
        FAIL() << "an out-of-range vt index was read";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.position().line, 5);
        EXPECT_EQ(e.position().column, 7);  // the corner 2/2
        EXPECT_NE(std::string(e.what()).find("texture coordinate index 2 is out of range"), std::string::npos)
            << e.what();
    }
}

const char* kTwoMaterialObj =
    "mtllib two.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
    "f 1 2 3\n"  // before any usemtl
    "usemtl red\nf 1 3 4\nf 1 2 5\n"
    "usemtl shiny\nf 2 3 5\n"
    "usemtl red\nf 3 4 5\n";

std::size_t triangles_of(const Scene& scene, std::size_t object) {
    const auto* mesh = dynamic_cast<const Mesh*>(scene.world->shapes.at(object).get());
    return mesh ? mesh->triangles().size() : 0;
}

TEST(ObjMaterial, AMeshTakesTheFacesOfOneUsemtl) {
    test::TempDir dir;
    dir.write("two.obj", kTwoMaterialObj);
    const std::string base = (dir / "two.obj").string();
    const Scene scene = test::scene_from_text(
        "objects:\n"
        "  - {type: mesh, file: '" +
        base +
        "', obj_material: red}\n"
        "  - {type: mesh, file: '" +
        base +
        "', obj_material: shiny}\n"
        "  - {type: mesh, file: '" +
        base + "', obj_material: ''}\n");
    EXPECT_EQ(triangles_of(scene, 0), 3u);
    EXPECT_EQ(triangles_of(scene, 1), 1u);
    EXPECT_EQ(triangles_of(scene, 2), 1u);
    try {
        test::scene_from_text("objects:\n  - {type: mesh, file: '" + base + "', obj_material: rde}\n");
        FAIL() << "an unknown usemtl name was accepted";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.position().line, 2);
        EXPECT_NE(std::string(e.what()).find("did you mean 'red'"), std::string::npos) << e.what();
    }
}

TEST(InlineMesh, PositionsIndicesAndUvsBuildAMesh) {
    const Scene scene = test::scene_from_text(
        "objects:\n"
        "  - {type: mesh, positions: [0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0], indices: [0, 1, 2, 0, 2, 3],\n"
        "     uvs: [0, 0, 1, 0, 1, 1, 0, 1]}\n");
    Hit hit;
    ASSERT_TRUE(scene.world->shapes.at(0)->intersect(Ray{{1.5, 0.75, 1}, {0, 0, -1}}, kInf, hit));
    EXPECT_NEAR(surface_uv(hit).x, 0.75, 1e-12);
    EXPECT_NEAR(surface_uv(hit).y, 0.75, 1e-12);
    EXPECT_EQ(triangles_of(scene, 0), 2u);
}

TEST(InlineMesh, BadDataIsAPositionedError) {
    const auto expect_error = [](const std::string& object, int column, const std::string& words) {
        try {
            test::scene_from_text("objects:\n  - " + object + "\n");
            FAIL() << "accepted: " << object;
        } catch (const SceneError& e) {
            EXPECT_EQ(e.position().line, 2) << e.what();
            EXPECT_EQ(e.position().column, column) << e.what();
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    expect_error("{type: mesh, positions: [0, 0, 0, 1, 0, 0, 0, 1, 0], indices: [0, 1, 3]}", 67,
                 "index 2 is not a whole number from 0 to 3 - 1");
    expect_error("{type: mesh, positions: [0, 0, 0, 1, 0], indices: [0, 1, 2]}", 29, "3 for each item");
    expect_error("{type: mesh, positions: [0, 0, 0, 1, 0, 0, 0, 1, 0], indices: [0, 1, 2], uvs: [0, 0]}", 83,
                 "one uv for each of the 3 positions");
}

// A material as the writer puts it on one line: as an item of a list, "- {type: …}".
std::string one_line(const Node& material) {
    Node list;
    list.kind = Node::Kind::Sequence;
    list.items.push_back(material);
    return write_scene_yaml(list);
}

// The glint material `mtl` (one newmtl block) maps to, and the warnings it gives.
Node mapped(const std::string& mtl, std::vector<SceneWarning>* warnings_out = nullptr) {
    test::TempDir dir;
    const std::vector<MtlMaterial> materials = load_mtl(dir.write("m.mtl", mtl), {});
    EXPECT_EQ(materials.size(), 1u);
    std::vector<SceneWarning> warnings;
    Node node = material_from_mtl(materials.at(0), dir.path() / "textures", dir.path(), warnings);
    if (warnings_out) {
        *warnings_out = warnings;
    }
    return node;
}

TEST(MtlMapping, EachKindOfMaterialBecomesItsGlintMaterial) {
    EXPECT_EQ(one_line(mapped("newmtl clay\nKd 0.5 0.25 0.125\n")),
              "- {type: matte, albedo: [0.5, 0.25, 0.125]}\n");
    EXPECT_EQ(one_line(mapped("newmtl shiny\nKd 0.5 0.5 0.5\nKs 0.25 0.25 0.25\nNs 100\nillum 2\n")),
              "- {type: phong, diffuse: [0.5, 0.5, 0.5], specular: [0.25, 0.25, 0.25], exponent: 100}\n");
    EXPECT_EQ(one_line(mapped("newmtl lamp\nKe 10 9 8\n")), "- {type: emissive, radiance: [10, 9, 8]}\n");
    EXPECT_EQ(one_line(mapped("newmtl water\nillum 7\nNi 1.33\n")), "- {type: dielectric, ior: 1.33}\n");
    EXPECT_EQ(one_line(mapped("newmtl chrome\nKd 0 0 0\nKs 0.9 0.9 0.9\nillum 3\n")),
              "- {type: mirror, reflectance: [0.9, 0.9, 0.9]}\n");
    EXPECT_EQ(one_line(mapped("newmtl wood\nKd 1 1 1\nmap_Kd wood.png\n")),
              "- {type: matte, albedo: {type: image, file: textures/wood.png}}\n");
    // Phong cannot take a map with a specular colour (kd + ks ≤ 1 everywhere): plastic can.
    EXPECT_EQ(one_line(mapped("newmtl varnish\nKd 1 1 1\nKs 0.25 0.25 0.25\nmap_Kd wood.png\n")),
              "- {type: plastic, diffuse: {type: image, file: textures/wood.png}}\n");
}

TEST(MtlMapping, WhatIsLeftOutIsAWarningAtItsStatement) {
    std::vector<SceneWarning> warnings;
    mapped("newmtl odd\nKd 0.5 0.5 0.5\n  map_Bump bumps.png\nd 0.5\n", &warnings);
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_EQ(warnings[0].pos.line, 3);
    EXPECT_EQ(warnings[0].pos.column, 3);
    EXPECT_NE(warnings[0].to_string().find("m.mtl:3:3: warning: 'map_Bump' is not read by glint"),
              std::string::npos)
        << warnings[0].to_string();
    EXPECT_EQ(warnings[1].pos.line, 4);
    EXPECT_NE(warnings[1].message.find("rendered opaque"), std::string::npos);
}

TEST(MtlMapping, MalformedStatementsArePositionedErrors) {
    test::TempDir dir;
    const auto expect_error = [&](const std::string& text, int line, int column, const std::string& words) {
        try {
            load_mtl(dir.write("bad.mtl", text), {});
            FAIL() << "accepted: " << text;
        } catch (const SceneError& e) {
            EXPECT_EQ(e.position().line, line) << e.what();
            EXPECT_EQ(e.position().column, column) << e.what();
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    expect_error("Kd 1 1 1\n", 1, 1, "before any 'newmtl'");
    expect_error("newmtl a\nKd 1 x 1\n", 2, 6, "expected a finite number, found 'x'");
    expect_error("newmtl a\nKd spectral file.spd\n", 2, 4, "give r g b");
    expect_error("newmtl a\nd 2\n", 2, 3, "from 0 to 1");
    expect_error("newmtl a\nillum 2.5\n", 2, 7, "whole number");
}

// A square 2 × 1 facing the camera, textured by an 8 × 1 PFM (linear: left half 0.25, right half
// 0.75; bilinear filtering blends them only within half a texel, 1/16, of u = 0, 0.5 and 1), under
// the importer's white sky. A matte surface that sees only a sky of radiance 1 reflects radiance
// equal to its albedo, so the image shows the texture's values themselves.
TEST(ObjImport, ATexturedModelRendersItsTextureUnderTheDefaultSky) {
    test::TempDir dir;
    dir.write("square.obj", std::string("mtllib square.mtl\nusemtl tex\n") + kSquareObj);
    dir.write("square.mtl", "newmtl tex\nKd 1 1 1\nmap_Kd tex.pfm\n");
    Image texture(8, 1);
    for (std::size_t i = 0; i < texture.rgb.size(); ++i) {
        texture.rgb[i] = i < 12 ? 0.25f : 0.75f;
    }
    const std::vector<unsigned char> pfm = encode_pfm(texture);
    dir.write("tex.pfm", std::string(pfm.begin(), pfm.end()));
    SceneDesc desc = load_scene(dir / "square.obj");
    RenderFlags flags;
    flags.width = 64;
    flags.height = 32;
    flags.samples_per_pixel = 64;
    const Scene scene = build_scene(desc, flags);
    const Film film = test::render_film(scene);
    // The default camera frames the square's bounding sphere (radius √5/2 at 1.1 × radius / sin 20°,
    // fov 40°): the square covers about columns 20–44 (u = (x − 20) / 24) and rows 10–22. Blocks well
    // inside each half of the texture: u from 0.1 to 0.3, and from 0.7 to 0.9.
    const auto block_mean = [&](int x0) {
        double sum = 0;
        int n = 0;
        for (int y = 13; y < 19; ++y) {
            for (int x = x0; x < x0 + 5; ++x) {
                sum += film.pixel(x, y).g;
                ++n;
            }
        }
        return sum / n;
    };
    EXPECT_NEAR(block_mean(22), 0.25, 0.02);
    EXPECT_NEAR(block_mean(37), 0.75, 0.04);
}

TEST(ObjImport, ConvertWritesAYamlThatRendersTheSameBits) {
    test::TempDir dir;
    dir.write("two.obj", kTwoMaterialObj);
    dir.write("two.mtl", "newmtl red\nKd 0.8 0.1 0.1\nnewmtl shiny\nKd 0.2 0.2 0.2\nKs 0.5 0.5 0.5\nNs 20\n");
    std::filesystem::create_directories(dir / "elsewhere");
    const std::string settings = " --width 24 --height 16 --spp 4 -q";
    const auto converted = test::run_glint("convert '" + (dir / "two.obj").string() + "' -o '" +
                                           (dir / "elsewhere/two.yaml").string() + "'");
    ASSERT_EQ(converted.exit_code, 0) << converted.output;
    const auto a = test::run_glint("render '" + (dir / "two.obj").string() + "' -o '" +
                                   (dir / "a.pfm").string() + "'" + settings);
    const auto b = test::run_glint("render '" + (dir / "elsewhere/two.yaml").string() + "' -o '" +
                                   (dir / "b.pfm").string() + "'" + settings);
    ASSERT_EQ(a.exit_code, 0) << a.output;
    ASSERT_EQ(b.exit_code, 0) << b.output;
    const auto read = [](const std::filesystem::path& path) {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    EXPECT_FALSE(read(dir / "a.pfm").empty());
    EXPECT_EQ(read(dir / "a.pfm"), read(dir / "b.pfm"));
    // The warnings say what the file did not: the camera and the light.
    EXPECT_NE(a.output.find("warning: an OBJ file has no camera"), std::string::npos) << a.output;
    EXPECT_NE(a.output.find("warning: nothing in the OBJ file emits light"), std::string::npos) << a.output;
}

TEST(ObjImport, AMalformedFileIsAPositionedErrorAndExit2) {
    test::TempDir dir;
    dir.write("bad.obj", "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    dir.write("bad.mtl", "newmtl a\nNs fast\n");
    const auto result = test::run_glint("render '" + (dir / "bad.obj").string() + "' -o '" +
                                        (dir / "bad.png").string() + "' -q");
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_NE(result.output.find("bad.mtl:2:4: error: expected a finite number, found 'fast'"),
              std::string::npos)
        << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.png"));
}

TEST(ObjImport, AMissingMaterialLibraryIsAWarningNotAnError) {
    test::TempDir dir;
    dir.write("lost.obj", "mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    const SceneDesc desc = load_scene(dir / "lost.obj");
    ASSERT_FALSE(desc.warnings.empty());
    EXPECT_EQ(desc.warnings[0].pos.line, 1);
    EXPECT_EQ(desc.warnings[0].pos.column, 8);
    EXPECT_NE(desc.warnings[0].message.find("'nowhere.mtl' not found"), std::string::npos);
    EXPECT_NO_THROW(build_scene(desc));
}

}  // namespace
}  // namespace glint
