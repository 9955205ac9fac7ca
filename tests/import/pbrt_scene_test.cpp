// The pbrt-v4 importer against values known without its code: pbrt-v4's conventions (its transforms,
// its camera's handedness and fov, its defaults) worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "glint/import/pbrt_convert.hpp"
#include "glint/import/pbrt_scene.hpp"
#include "glint/scene/scene_writer.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

SceneDesc import(const std::string& text) {
    return import_pbrt_text(text, "t.pbrt", ".");
}

// The node at a dotted path: "objects.0.radius".
const Node& at(const Node& root, const std::string& path) {
    const Node* node = &root;
    std::size_t start = 0;
    while (start <= path.size()) {
        const std::size_t end = std::min(path.find('.', start), path.size());
        const std::string key = path.substr(start, end - start);
        if (node->is_sequence()) {
            node = &node->items.at(std::stoul(key));
        } else {
            node = node->find(key);
        }
        if (!node) {
            throw std::runtime_error("no " + path);
        }
        start = end + 1;
    }
    return *node;
}

std::vector<double> numbers_at(const Node& root, const std::string& path) {
    std::vector<double> numbers;
    for (const Node& item : at(root, path).items) {
        numbers.push_back(std::stod(item.scalar));
    }
    return numbers;
}

double number_at(const Node& root, const std::string& path) {
    return std::stod(at(root, path).scalar);
}

bool warned(const SceneDesc& desc, const std::string& part) {
    for (const SceneWarning& w : desc.warnings) {
        if (w.message.find(part) != std::string::npos) {
            return true;
        }
    }
    return false;
}

// A camera whose transform mirrors (as exporters write it), so that the importer leaves the world as
// it is and the matrices below are pbrt's own.
const std::string kUnmirroredCamera = "Scale -1 1 1\nLookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\n";

TEST(PbrtScene, SphereRadiusAndTransform) {
    const SceneDesc desc =
        import(kUnmirroredCamera +
               "WorldBegin\nTranslate 1 2 3\nScale 2 2 2\nShape \"sphere\" \"float radius\" 0.5\n");
    EXPECT_EQ(at(desc.root, "objects.0.type").scalar, "sphere");
    EXPECT_EQ(number_at(desc.root, "objects.0.radius"), 0.5);
    EXPECT_EQ(numbers_at(desc.root, "objects.0.transform.matrix"),
              (std::vector<double>{2, 0, 0, 1, 0, 2, 0, 2, 0, 0, 2, 3}));
}

TEST(PbrtScene, NestedAttributesRestoreTheTransform) {
    const SceneDesc desc =
        import(kUnmirroredCamera +
               "WorldBegin\nTranslate 1 0 0\n"
               "AttributeBegin\n  Scale 2 2 2\n"
               "  AttributeBegin\n    Translate 0 1 0\n    Shape \"sphere\"\n  AttributeEnd\n"
               "  Shape \"sphere\"\n"
               "AttributeEnd\n"
               "Shape \"sphere\"\n");
    // pbrt post-multiplies: the first sphere is at 1 + 2·((0, 1, 0) + p).
    EXPECT_EQ(numbers_at(desc.root, "objects.0.transform.matrix"),
              (std::vector<double>{2, 0, 0, 1, 0, 2, 0, 2, 0, 0, 2, 0}));
    EXPECT_EQ(numbers_at(desc.root, "objects.1.transform.matrix"),
              (std::vector<double>{2, 0, 0, 1, 0, 2, 0, 0, 0, 0, 2, 0}));
    EXPECT_EQ(numbers_at(desc.root, "objects.2.transform.matrix"),
              (std::vector<double>{1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0}));
}

TEST(PbrtScene, WorldBeginResetsTheTransformAndPlainLookAtMirrorsTheWorld) {
    // A plain LookAt keeps handedness, so glint's world is pbrt's with x negated.
    const SceneDesc desc = import(
        "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n"
        "Shape \"sphere\"\n");
    EXPECT_EQ(numbers_at(desc.root, "objects.0.transform.matrix"),
              (std::vector<double>{-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}));
    EXPECT_EQ(numbers_at(desc.root, "camera.eye"), (std::vector<double>{0, 0, -5}));
    EXPECT_EQ(numbers_at(desc.root, "camera.look_at"), (std::vector<double>{0, 0, -4}));
    EXPECT_EQ(numbers_at(desc.root, "camera.up"), (std::vector<double>{0, 1, 0}));
}

// pbrt's image: camera +x is the image's right. A sphere at pbrt x = −1 seen by a camera whose +x is
// world +x (LookAt from −z) is left of centre; with `Scale -1 1 1` first, camera +x is world −x, and it
// is right of centre. glint's image must agree in both.
TEST(PbrtScene, TheImageIsPbrtsNotItsMirrorImage) {
    const std::string world =
        "Film \"rgb\" \"integer xresolution\" 32 \"integer yresolution\" 16\n"
        "Sampler \"independent\" \"integer pixelsamples\" 1\n"
        "WorldBegin\nAttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\nTranslate -1 0 0\n"
        "Shape \"sphere\" \"float radius\" 0.5\nAttributeEnd\n";
    for (const bool exporter_mirror : {false, true}) {
        const std::string camera = std::string(exporter_mirror ? "Scale -1 1 1\n" : "") +
                                   "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 40\n";
        const Scene scene = build_scene(import(camera + world));
        const Film film = test::render_film(scene);
        double left = 0, right = 0;
        for (int y = 0; y < film.height(); ++y) {
            for (int x = 0; x < film.width(); ++x) {
                (x < film.width() / 2 ? left : right) += film.pixel(x, y).r;
            }
        }
        if (exporter_mirror) {
            EXPECT_GT(right, 0);
            EXPECT_EQ(left, 0);
        } else {
            EXPECT_GT(left, 0);
            EXPECT_EQ(right, 0);
        }
    }
}

TEST(PbrtScene, FovSpansTheShorterImageAxis) {
    const auto fov_for = [](int width, int height) {
        const SceneDesc desc = import(
            "Camera \"perspective\" \"float fov\" 60\nFilm \"rgb\" \"integer xresolution\" " +
            std::to_string(width) + " \"integer yresolution\" " + std::to_string(height) + "\nWorldBegin\n");
        return number_at(desc.root, "camera.fov");
    };
    // 2:1: the height is the shorter axis, and glint's fov is vertical: the same angle.
    EXPECT_NEAR(fov_for(200, 100), 60, 1e-12);
    // 1:2: pbrt's 60° spans the width; the height is twice it: 2·atan(2·tan 30°) = 98.2132°.
    EXPECT_NEAR(fov_for(100, 200), 98.2132, 1e-4);
}

TEST(PbrtScene, CameraFilmSamplerIntegrator) {
    const SceneDesc desc = import(
        "Camera \"perspective\" \"float lensradius\" 0.1 \"float focaldistance\" 4\n"
        "Film \"rgb\" \"integer xresolution\" 64 \"integer yresolution\" 32\n"
        "Sampler \"zsobol\" \"integer pixelsamples\" 8\nIntegrator \"volpath\" \"integer maxdepth\" 7\n"
        "PixelFilter \"box\"\nWorldBegin\n");
    EXPECT_EQ(at(desc.root, "camera.type").scalar, "thin-lens");
    EXPECT_EQ(number_at(desc.root, "camera.lens_radius"), 0.1);
    EXPECT_EQ(number_at(desc.root, "camera.focus_distance"), 4);
    EXPECT_EQ(number_at(desc.root, "render.width"), 64);
    EXPECT_EQ(number_at(desc.root, "render.height"), 32);
    EXPECT_EQ(number_at(desc.root, "render.samples"), 8);
    EXPECT_EQ(at(desc.root, "render.sampler").scalar, "sobol");
    EXPECT_EQ(at(desc.root, "render.integrator.type").scalar, "path");
    EXPECT_EQ(number_at(desc.root, "render.integrator.max_depth"), 7);
    EXPECT_EQ(at(desc.root, "render.filter").scalar, "box");
    // pbrt-v4's defaults: maxdepth 5, 1280 × 720.
    const SceneDesc defaults = import("WorldBegin\n");
    EXPECT_EQ(number_at(defaults.root, "render.integrator.max_depth"), 5);
    EXPECT_EQ(number_at(defaults.root, "render.width"), 1280);
    EXPECT_EQ(number_at(defaults.root, "camera.fov"), 90);

    const SceneDesc ortho = import(
        "Camera \"orthographic\" \"float screenwindow\" [-2 2 -1 1]\n"
        "Film \"rgb\" \"integer xresolution\" 64 \"integer yresolution\" 32\nWorldBegin\n");
    EXPECT_EQ(at(ortho.root, "camera.type").scalar, "orthographic");
    EXPECT_EQ(number_at(ortho.root, "camera.height"), 2);
}

TEST(PbrtScene, NamedMaterialsAreLookedUpByName) {
    const SceneDesc desc = import(
        "WorldBegin\nMakeNamedMaterial \"red\" \"string type\" \"diffuse\" \"rgb reflectance\" [0.8 0.1 "
        "0.1]\n"
        "MakeNamedMaterial \"glass\" \"string type\" \"dielectric\" \"float eta\" 1.33\n"
        "NamedMaterial \"red\"\nShape \"sphere\"\n"
        "AttributeBegin\nNamedMaterial \"glass\"\nShape \"sphere\"\nAttributeEnd\nShape \"sphere\"\n");
    EXPECT_EQ(at(desc.root, "objects.0.material").scalar, "red");
    EXPECT_EQ(at(desc.root, "objects.1.material").scalar, "glass");
    EXPECT_EQ(at(desc.root, "objects.2.material").scalar, "red");
    EXPECT_EQ(at(desc.root, "materials.red.type").scalar, "matte");
    EXPECT_EQ(numbers_at(desc.root, "materials.red.albedo"), (std::vector<double>{0.8, 0.1, 0.1}));
    EXPECT_EQ(number_at(desc.root, "materials.glass.ior"), 1.33);
    try {
        import("WorldBegin\nNamedMaterial \"blue\"\nShape \"sphere\"\n");
        FAIL();
    } catch (const SceneError& e) {
        EXPECT_EQ(e.position().line, 2);
        EXPECT_NE(e.message().find("unknown named material 'blue'"), std::string::npos);
    }
}

TEST(PbrtScene, MaterialsAndTheirApproximations) {
    const SceneDesc desc = import(
        "WorldBegin\nMaterial \"conductor\" \"spectrum eta\" \"metal-Au-eta\" \"spectrum k\" \"metal-Au-k\" "
        "\"float roughness\" 0.0625\nShape \"sphere\"\n"
        "Material \"coateddiffuse\" \"rgb reflectance\" [0.2 0.3 0.4]\nShape \"sphere\"\n"
        "Material \"interface\"\nShape \"sphere\"\n"
        "Texture \"checks\" \"spectrum\" \"checkerboard\" \"float uscale\" 4 \"float vscale\" 4 "
        "\"rgb tex1\" [1 0 0]\nMaterial \"diffuse\" \"texture reflectance\" \"checks\"\nShape \"sphere\"\n"
        "Material \"dielectric\" \"spectrum eta\" \"glass-BK7\" \"float roughness\" 0.1\nShape \"sphere\"\n");
    const Node& objects = at(desc.root, "objects");
    ASSERT_EQ(objects.items.size(), 4u);  // the interface sphere has no surface
    const std::string gold = at(objects, "0.material").scalar;
    EXPECT_EQ(at(desc.root, "materials." + gold + ".type").scalar, "metal");
    // Gold at 630 nm: η 0.1837, κ 3.0663; F0 = ((η−1)² + κ²) / ((η+1)² + κ²) = 10.0685 / 10.8033.
    EXPECT_NEAR(numbers_at(desc.root, "materials." + gold + ".reflectance")[0], 0.93199, 1e-4);
    // pbrt's α = √0.0625 = 0.25 (remapped); glint's roughness = √α = 0.5.
    EXPECT_EQ(number_at(desc.root, "materials." + gold + ".roughness"), 0.5);
    const std::string plastic = at(objects, "1.material").scalar;
    EXPECT_EQ(at(desc.root, "materials." + plastic + ".type").scalar, "plastic");
    EXPECT_EQ(number_at(desc.root, "materials." + plastic + ".ior"), 1.5);
    const std::string checked = at(objects, "2.material").scalar;
    EXPECT_EQ(at(desc.root, "materials." + checked + ".albedo.type").scalar, "checker");
    EXPECT_EQ(number_at(desc.root, "materials." + checked + ".albedo.scale"), 4);
    EXPECT_EQ(number_at(desc.root, "materials." + at(objects, "3.material").scalar + ".ior"), 1.5185);
    EXPECT_TRUE(warned(desc, "glint's dielectric is smooth"));
}

TEST(PbrtScene, AreaLightsLightsAndWarnings) {
    const SceneDesc desc = import(
        "WorldBegin\nLightSource \"point\" \"rgb I\" [1 2 3] \"point3 from\" [1 2 3]\n"
        "LightSource \"distant\" \"point3 from\" [0 1 0] \"point3 to\" [0 0 0] \"float scale\" 2\n"
        "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [5 5 5] \"bool twosided\" true\n"
        "Shape \"disk\" \"float radius\" 2 \"float phimax\" 180 \"float unknown\" 1\nAttributeEnd\n");
    EXPECT_EQ(at(desc.root, "lights.0.type").scalar, "point");
    EXPECT_EQ(numbers_at(desc.root, "lights.0.position"), (std::vector<double>{-1, 2, 3}));  // mirrored
    EXPECT_EQ(numbers_at(desc.root, "lights.0.intensity"), (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(numbers_at(desc.root, "lights.1.direction"), (std::vector<double>{0, -1, 0}));
    EXPECT_EQ(number_at(desc.root, "lights.1.scale"), 2);
    EXPECT_EQ(at(desc.root, "objects.0.material.type").scalar, "emissive");
    EXPECT_EQ(numbers_at(desc.root, "objects.0.material.radiance"), (std::vector<double>{5, 5, 5}));
    EXPECT_EQ(at(desc.root, "objects.0.material.two_sided").scalar, "true");
    EXPECT_TRUE(warned(desc, "glint's disk is whole"));
    EXPECT_TRUE(warned(desc, "'unknown' is not read by glint"));
    for (const SceneWarning& w : desc.warnings) {
        EXPECT_TRUE(w.pos.file) << w.message;  // every warning is positioned
    }
}

TEST(PbrtScene, MeshesAndInstances) {
    const SceneDesc desc =
        import(kUnmirroredCamera +
               "WorldBegin\nObjectBegin \"tri\"\nShape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] "
               "\"point2 uv\" [0 0 1 0 0 1]\nObjectEnd\n"
               "ObjectInstance \"tri\"\nTranslate 5 0 0\nObjectInstance \"tri\"\n"
               "Shape \"bilinearmesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0 1 1 0] \"integer indices\" [0 1 2 3]\n"
               "Shape \"plymesh\" \"string filename\" \"m.ply\"\n");
    EXPECT_EQ(numbers_at(desc.root, "objects.0.indices"), (std::vector<double>{0, 1, 2}));
    EXPECT_EQ(numbers_at(desc.root, "objects.0.uvs"), (std::vector<double>{0, 0, 1, 0, 0, 1}));
    EXPECT_EQ(at(desc.root, "objects.0").find("transform"), nullptr);
    EXPECT_EQ(numbers_at(desc.root, "objects.1.transform.matrix"),
              (std::vector<double>{1, 0, 0, 5, 0, 1, 0, 0, 0, 0, 1, 0}));
    EXPECT_EQ(numbers_at(desc.root, "objects.2.indices"), (std::vector<double>{0, 1, 3, 0, 3, 2}));
    EXPECT_EQ(at(desc.root, "objects.3.file").scalar, "m.ply");
}

TEST(PbrtScene, LoopSubdivisionOfATetrahedron) {
    // A regular tetrahedron about the origin: V − E + F = 2 with V = 4, E = 6, F = 4. Each level adds a
    // vertex per edge (V' = V + E) and splits each face in 4 (E' = 2E + 3F, F' = 4F).
    const double s = 1;
    pbrt::TriangleMesh tetrahedron{{s, s, s, s, -s, -s, -s, s, -s, -s, -s, s},
                                   {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2}};
    const std::size_t vertices[] = {4, 10, 34, 130};
    for (int levels = 0; levels <= 3; ++levels) {
        const pbrt::TriangleMesh fine = pbrt::loop_subdivide(tetrahedron, levels);
        EXPECT_EQ(fine.positions.size() / 3, vertices[levels]);
        EXPECT_EQ(fine.indices.size() / 3, 4u << (2 * levels));
    }
    // One level by hand, for the corner v (valence 3, β = 3/16; the other corners sum to −v): it moves
    // to 7/16 v − 3/16 v = v/4; its new neighbours, the edge points 3/8 (v + w) + 1/8 (−v − w) = (v + w)/4,
    // sum to v/2; the limit mask γ = 1/(3 + 3/(8β)) = 1/5 puts it at 2/5 · v/4 + 1/5 · v/2 = v/5.
    const pbrt::TriangleMesh once = pbrt::loop_subdivide(tetrahedron, 1);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(once.positions[k], tetrahedron.positions[k] / 5, 1e-12);
    }
}

TEST(PbrtScene, ConvertRoundTripsToTheSameTreeAndTheSameBits) {
    const std::string text =
        kUnmirroredCamera +
        "Film \"rgb\" \"integer xresolution\" 24 \"integer yresolution\" 16\n"
        "Sampler \"halton\" \"integer pixelsamples\" 2\nWorldBegin\n"
        "LightSource \"infinite\" \"rgb L\" [0.3 0.4 0.5]\n"
        "Material \"conductor\" \"spectrum eta\" \"metal-Cu-eta\" \"spectrum k\" \"metal-Cu-k\"\n"
        "Rotate 33.3 1 2 3\nShape \"sphere\" \"float radius\" 0.7\n"
        "AttributeBegin\nAreaLightSource \"diffuse\" \"blackbody L\" 3000\nTranslate 0 2 0\n"
        "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 0 1]\nAttributeEnd\n";
    const SceneDesc imported = import(text);
    const std::string yaml = write_scene_yaml(imported.root);
    const SceneDesc reread = parse_scene_text(yaml, "converted.yaml", ".");
    EXPECT_EQ(write_scene_yaml(reread.root), yaml);
    const Film a = test::render_film(build_scene(imported));
    const Film b = test::render_film(build_scene(reread));
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            EXPECT_EQ(a.pixel(x, y).r, b.pixel(x, y).r);
            EXPECT_EQ(a.pixel(x, y).g, b.pixel(x, y).g);
            EXPECT_EQ(a.pixel(x, y).b, b.pixel(x, y).b);
        }
    }
}

TEST(PbrtScene, TheCliRendersConvertsAndRefusesWithExitCode2) {
    test::TempDir dir;
    const auto scene = dir.write("s.pbrt",
                                 "Film \"rgb\" \"integer xresolution\" 8 \"integer yresolution\" 8\n"
                                 "WorldBegin\nShape \"sphere\"\n");
    const test::CommandResult render =
        test::run_glint("render '" + scene.string() + "' --quiet -o '" + (dir / "s.pfm").string() + "'");
    EXPECT_EQ(render.exit_code, 0) << render.output;
    const test::CommandResult convert =
        test::run_glint("convert '" + scene.string() + "' -o '" + (dir / "s.yaml").string() + "'");
    EXPECT_EQ(convert.exit_code, 0) << convert.output;
    EXPECT_TRUE(std::filesystem::exists(dir / "s.yaml"));
    const auto bad = dir.write("bad.pbrt", "WorldBegin\n  Shape \"sphere\" \"float radius\" [1\n");
    const test::CommandResult refused = test::run_glint("render '" + bad.string() + "' --quiet");
    EXPECT_EQ(refused.exit_code, 2);
    EXPECT_NE(refused.output.find("bad.pbrt:3:1: error: the list of 'radius' opened at line 2 is not closed"),
              std::string::npos)
        << refused.output;
}

// Constructs that multiply what they cost are refused at their statement before they are built.
TEST(PbrtScene, MultiplyingConstructsAreBounded) {
    std::string bomb = "WorldBegin\nTexture \"t0\" \"spectrum\" \"constant\" \"rgb value\" [1 0 0]\n";
    for (int i = 1; i < 40; ++i) {  // each checkerboard holds the previous one twice: 2^39 values
        bomb += "Texture \"t" + std::to_string(i) + "\" \"spectrum\" \"checkerboard\" \"texture tex1\" \"t" +
                std::to_string(i - 1) + "\" \"texture tex2\" \"t" + std::to_string(i - 1) + "\"\n";
    }
    EXPECT_THROW(import(bomb), SceneError);
    std::string instances = "WorldBegin\nObjectBegin \"o\"\nShape \"sphere\"\nObjectEnd\n";
    for (int i = 0; i < 100'000; ++i) {
        instances += "ObjectInstance \"o\"\n";
    }
    EXPECT_THROW(import(instances), SceneError);
    std::string deep = "WorldBegin\n";
    for (int i = 0; i < 2000; ++i) {
        deep += "AttributeBegin\n";
    }
    EXPECT_THROW(import(deep), SceneError);
    EXPECT_THROW(
        import("WorldBegin\nShape \"loopsubdiv\" \"integer levels\" 1e300 \"point3 P\" [0 0 0 1 0 0 0 1 0]"),
        SceneError);
}

// The example scene, through the command line: it renders, and its conversion renders the same bits
// (convert rewrites the PLY's path for the YAML's folder).
TEST(PbrtScene, TheExampleConvertsToTheSameImage) {
    test::TempDir dir;
    const std::string example = std::string(GLINT_SOURCE_DIR) + "/examples/pbrt-cornell.pbrt";
    const std::string small = " --width 24 --height 24 --spp 2 --quiet -o '";
    const test::CommandResult direct =
        test::run_glint("render '" + example + "'" + small + (dir / "a.pfm").string() + "'");
    ASSERT_EQ(direct.exit_code, 0) << direct.output;
    const test::CommandResult convert =
        test::run_glint("convert '" + example + "' -o '" + (dir / "converted.yaml").string() + "'");
    ASSERT_EQ(convert.exit_code, 0) << convert.output;
    const test::CommandResult converted = test::run_glint("render '" + (dir / "converted.yaml").string() +
                                                          "'" + small + (dir / "b.pfm").string() + "'");
    ASSERT_EQ(converted.exit_code, 0) << converted.output;
    EXPECT_EQ(test::run_command("cmp '" + (dir / "a.pfm").string() + "' '" + (dir / "b.pfm").string() + "'")
                  .exit_code,
              0);
}

}  // namespace
}  // namespace glint
