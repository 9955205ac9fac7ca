// OBJ and PLY loading on small files written here: polygons, negative indices, normals missing or
// broken, binary byte orders, triangle strips, and malformed files (a positioned error, never a crash).
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <fstream>

#include "glint/geometry/mesh.hpp"
#include "glint/geometry/mesh_io/mesh_data.hpp"
#include "test_data.hpp"

namespace glint {
namespace {

std::filesystem::path write_file(const std::string& name, const std::string& bytes) {
    const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

// Loading `text` as file `name` fails with a SceneError at line:column of that file.
void expect_error_at(const std::string& name, const std::string& text, int line, int column,
                     const std::string& words) {
    const auto path = write_file(name, text);
    try {
        load_mesh_file(path);
        FAIL() << "no error for " << name;
    } catch (const SceneError& e) {
        ASSERT_TRUE(e.position().file);
        EXPECT_EQ(e.position().file->path, path.string());
        EXPECT_EQ(e.position().line, line) << e.what();
        EXPECT_EQ(e.position().column, column) << e.what();
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
}

TEST(ObjLoader, PolygonsBecomeFansAndNegativeIndicesCountBack) {
    const auto path = write_file("ngon.obj",
                                 "# a quad and a pentagon\n"
                                 "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                 "f 1 2 3 4\n"
                                 "v 0 0 1\nv 1 0 1\nv 2 1 1\nv 1 2 1\nv 0 1 1\n"
                                 "f -5 -4 -3 -2 -1\n");
    const MeshData mesh = load_obj(path);
    ASSERT_EQ(mesh.positions.size(), 9u);
    ASSERT_EQ(mesh.triangles.size(), 2u + 3u);
    EXPECT_TRUE(mesh.normals.empty());
    // The pentagon's fan starts at its first corner, the fifth vertex of the file.
    const auto& fan = mesh.triangles[2];
    EXPECT_EQ(mesh.positions[fan[0]], Vec3(0, 0, 1));
    EXPECT_EQ(mesh.positions[fan[1]], Vec3(1, 0, 1));
    EXPECT_EQ(mesh.positions[fan[2]], Vec3(2, 1, 1));
    const Mesh shape(mesh);
    EXPECT_NEAR(shape.area(), 1.0 + 2.5, 1e-12);  // the pentagon (0,0)(1,0)(2,1)(1,2)(0,1): 2.5
}

TEST(ObjLoader, NormalsAreInterpolatedAndBrokenOnesRecomputed) {
    // A flat square whose corners have normals tilted outwards, except one zero normal and one corner
    // without any: those two are recomputed from the faces (straight up).
    const auto path = write_file("normals.obj",
                                 "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n"
                                 "vn -1 1 -1\nvn 1 1 -1\nvn 0 0 0\n"
                                 "f 1//1 4//3 3 2//2\n");
    const Mesh mesh(load_obj(path));
    Hit hit;
    // Straight down onto the middle: the interpolated normal is up (the tilts cancel).
    ASSERT_TRUE(mesh.intersect({{0.0, 5, 0.0}, {0, -1, 0}}, kInf, hit));
    EXPECT_NEAR(hit.t, 5, 1e-12);
    EXPECT_NEAR(std::abs(hit.normal.y), 1, 1e-12);
    EXPECT_NEAR(hit.shading_normal.y * hit.normal.y, std::abs(hit.shading_normal.y), 1e-12);  // same side
    // Near the corner with the zero normal: recomputed to the face normal, so the shading normal is
    // (nearly) vertical there.
    ASSERT_TRUE(mesh.intersect({{-0.999, 5, 0.999}, {0, -1, 0}}, kInf, hit));
    EXPECT_NEAR(std::abs(hit.shading_normal.y), 1, 1e-2);
    // Near the corner with normal (−1, 1, −1): tilted.
    ASSERT_TRUE(mesh.intersect({{-0.999, 5, -0.999}, {0, -1, 0}}, kInf, hit));
    EXPECT_NEAR(std::abs(hit.shading_normal.x), 1 / std::sqrt(3.0), 1e-2);
    EXPECT_TRUE(std::isfinite(length(hit.shading_normal)));
}

TEST(ObjLoader, MalformedFilesArePositionedErrors) {
    expect_error_at("bad_number.obj", "v 0 0 0\nv 1 oops 0\n", 2, 5, "expected a number");
    expect_error_at("bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 4, 7, "out of range");
    expect_error_at("zero_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 4, 3, "out of range");
    expect_error_at("negative_too_far.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", 4, 9, "out of range");
    expect_error_at("short_face.obj", "v 0 0 0\nv 1 0 0\nf 1 2\n", 3, 1, "three corners");
    expect_error_at("short_vertex.obj", "v 0 0\n", 1, 1, "three numbers");
    expect_error_at("bad_normal_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1//1 2//1 3//1\n", 4, 3,
                    "normal index");
    expect_error_at("nan.obj", "v 0 nan 0\n", 1, 5, "not finite");
    expect_error_at("empty.obj", "# nothing\n", 2, 1, "no faces");
}

// The same two-triangle mesh (a quad, and a strip of two triangles over its other side) as PLY text
// or binary in either byte order.
std::string ply_header(const std::string& format) {
    return "ply\nformat " + format +
           " 1.0\ncomment written by the test\nelement vertex 4\nproperty float x\nproperty float y\n"
           "property float z\nproperty double nx\nproperty double ny\nproperty double nz\nproperty uchar "
           "flags\n"
           "element face 1\nproperty list uchar int vertex_indices\nproperty int flags\n"
           "element tristrips 1\nproperty list int int vertex_indices\nend_header\n";
}

template <class T>
void put(std::string& out, T value, bool big_endian) {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if (big_endian == (std::endian::native == std::endian::little)) {
        std::reverse(raw, raw + sizeof(T));
    }
    out.append(reinterpret_cast<const char*>(raw), sizeof(T));
}

const float kQuad[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

std::string binary_ply(bool big_endian) {
    std::string out = ply_header(big_endian ? "binary_big_endian" : "binary_little_endian");
    for (const auto& v : kQuad) {
        put<float>(out, v[0], big_endian);
        put<float>(out, v[1], big_endian);
        put<float>(out, v[2], big_endian);
        put<double>(out, 0.0, big_endian);
        put<double>(out, 0.0, big_endian);
        put<double>(out, 1.0, big_endian);
        put<std::uint8_t>(out, 7, big_endian);
    }
    put<std::uint8_t>(out, 4, big_endian);  // the quad
    for (int i : {0, 1, 2, 3}) {
        put<std::int32_t>(out, i, big_endian);
    }
    put<std::int32_t>(out, 0, big_endian);
    put<std::int32_t>(out, 5, big_endian);  // a strip 0 1 3 2, a restart, then 3 2 1
    for (int i : {0, 1, 3, -1, 2}) {
        put<std::int32_t>(out, i, big_endian);
    }
    return out;
}

std::string ascii_ply() {
    return ply_header("ascii") +
           "0 0 0 0 0 1 7\n1 0 0 0 0 1 7\n1 1 0 0 0 1 7\n0 1 0 0 0 1 7\n"
           "4 0 1 2 3 0\n"
           "5 0 1 3 -1 2\n";
}

TEST(PlyLoader, AsciiAndBothBinaryByteOrdersGiveTheSameMesh) {
    const MeshData ascii = load_ply(write_file("quad_ascii.ply", ascii_ply()));
    const MeshData little = load_ply(write_file("quad_le.ply", binary_ply(false)));
    const MeshData big = load_ply(write_file("quad_be.ply", binary_ply(true)));
    for (const MeshData* mesh : {&ascii, &little, &big}) {
        ASSERT_EQ(mesh->positions.size(), 4u);
        EXPECT_EQ(mesh->positions[2], Vec3(1, 1, 0));
        ASSERT_EQ(mesh->normals.size(), 4u);
        EXPECT_EQ(mesh->normals[3], Vec3(0, 0, 1));
        // Two from the quad's fan, one from the strip (0 1 3); the strip "2" after −1 is too short.
        ASSERT_EQ(mesh->triangles.size(), 3u);
        EXPECT_EQ(mesh->triangles[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
        EXPECT_EQ(mesh->triangles[1], (std::array<std::uint32_t, 3>{0, 2, 3}));
        EXPECT_EQ(mesh->triangles[2], (std::array<std::uint32_t, 3>{0, 1, 3}));
    }
}

TEST(PlyLoader, StripsAlternateTheirWinding) {
    const std::string text =
        "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
        "element tristrips 1\nproperty list int int vertex_indices\nend_header\n"
        "0 0 0\n0 1 0\n1 0 0\n1 1 0\n2 0 0\n"
        "5 0 1 2 3 4\n";
    const MeshData mesh = load_ply(write_file("strip.ply", text));
    ASSERT_EQ(mesh.triangles.size(), 3u);
    for (const auto& tri : mesh.triangles) {
        // Every triangle of a strip faces the same way.
        const Vec3 n = cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                             mesh.positions[tri[2]] - mesh.positions[tri[0]]);
        EXPECT_LT(n.z, 0);
    }
}

TEST(PlyLoader, MalformedFilesArePositionedErrors) {
    expect_error_at("bad_magic.ply", "plx\n", 1, 1, "not a PLY file");
    expect_error_at("bad_format.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", 2, 8,
                    "unknown PLY format");
    expect_error_at("no_end.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", 3, 1, "end_header");
    std::string bad_index = ascii_ply();
    bad_index.replace(bad_index.find("4 0 1 2 3 0"), 11, "4 0 1 9 3 0");
    const int face_line = 22;  // 17 header lines, 4 vertices
    expect_error_at("bad_index.ply", bad_index, face_line, 7, "out of range");
    std::string bad_number = ascii_ply();
    bad_number.replace(bad_number.find("1 1 0 0 0 1 7"), 13, "1 x 0 0 0 1 7");
    expect_error_at("bad_number.ply", bad_number, face_line - 2, 3, "expected a number");
    // Binary, truncated: short of what the header's counts need at the least (each vertex 37 bytes,
    // each face and strip a count and an int), an error at the element's header line before anything is
    // read; short only of what the lists then claim, an error naming the byte offset and the element.
    struct Cut {
        std::size_t bytes;
        int line;  // 0: in the data
        const char* words;
    };
    for (const Cut& cut : {Cut{10, 0, "at byte"}, Cut{40, 15, "element 'tristrips' declares 1 records"},
                           Cut{100, 4, "element 'vertex' declares 4 records of at least 37 bytes"}}) {
        std::string truncated = binary_ply(false);
        truncated.resize(truncated.size() - cut.bytes);
        const auto path = write_file("truncated.ply", truncated);
        try {
            load_ply(path);
            FAIL() << "no error";
        } catch (const SceneError& e) {
            EXPECT_EQ(e.position().file->path, path.string());
            EXPECT_EQ(e.position().line, cut.line) << e.what();
            EXPECT_NE(std::string(e.what()).find(cut.words), std::string::npos) << e.what();
        }
    }
    std::string huge_list = binary_ply(true);
    const std::size_t face = ply_header("binary_big_endian").size() + 4 * (12 + 24 + 1);
    huge_list[face] = static_cast<char>(250);
    const auto path = write_file("huge_list.ply", huge_list);
    try {
        load_ply(path);
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("face 0"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("at byte " + std::to_string(face)), std::string::npos)
            << e.what();
    }
}

TEST(MeshFiles, EveryTruncationOrCorruptionIsAnErrorOrAMeshNeverACrash) {
    const std::string obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf -1 -2 -3\n";
    const std::pair<std::string, std::string> files[] = {
        {"t.ply", binary_ply(false)}, {"t.ply", binary_ply(true)}, {"t.ply", ascii_ply()}, {"t.obj", obj}};
    int errors = 0;
    for (const auto& [name, bytes] : files) {
        for (std::size_t size = 0; size < bytes.size(); size += 11) {
            for (int corrupt = 0; corrupt < 2; ++corrupt) {
                std::string damaged = bytes.substr(0, size);
                if (corrupt == 1 && size > 0) {
                    damaged[size / 2] = static_cast<char>(damaged[size / 2] ^ 0x5a);
                }
                try {
                    const MeshData mesh = load_mesh_file(write_file(name, damaged));
                    for (const auto& tri : mesh.triangles) {
                        for (std::uint32_t v : tri) {
                            ASSERT_LT(v, mesh.positions.size());
                        }
                    }
                } catch (const SceneError&) {
                    ++errors;
                }
            }
        }
    }
    EXPECT_GT(errors, 50);
}

TEST(MeshFiles, StanfordMeshesLoad) {
    GLINT_REQUIRE_DATA_FILE(igea_file, "meshes/igea.ply");
    GLINT_REQUIRE_DATA_FILE(dragon_file, "meshes/dragon_100k_vcg.ply");
    const MeshData igea = load_mesh_file(igea_file);  // one long triangle strip
    EXPECT_EQ(igea.positions.size(), 134345u);
    EXPECT_GT(igea.triangles.size(), igea.positions.size());  // a closed surface has about 2 V faces
    const MeshData dragon = load_mesh_file(dragon_file);
    EXPECT_EQ(dragon.positions.size(), 50000u);
    EXPECT_EQ(dragon.normals.size(), 50000u);
    EXPECT_EQ(dragon.triangles.size(), 100000u);
    EXPECT_THROW(load_mesh_file(igea_file.parent_path() / "missing.obj"), SceneError);
    EXPECT_THROW(load_mesh_file(write_file("mesh.stl", "solid")), SceneError);
}

}  // namespace
}  // namespace glint
