// Hostile mesh files: counts that the file cannot hold or the limits do not allow, elements that would
// make positions and normals disagree, coordinates beyond float's range, indices out of range, huge
// lists and polygons. Each must give a positioned error (file:line:col for text, the byte and record for
// binary data), quickly: the counts are checked against the file's size and the limits before anything
// is read or allocated, so every one of these tests finishes in milliseconds.
#include <gtest/gtest.h>

#include <bit>
#include <chrono>
#include <cstring>
#include <fstream>

#include "glint/geometry/mesh.hpp"
#include "glint/geometry/mesh_io/mesh_data.hpp"

namespace glint {
namespace {

std::filesystem::path write_file(const std::string& name, const std::string& bytes) {
    const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
}

// Loading `bytes` as file `name` fails, within a second, with a SceneError whose message holds `words`
// and whose position is line:column of the file (line 0: in the file but no line, as for binary data;
// line −1: no position, an error about the file as a whole). Returns the error.
SceneError expect_error(const std::string& name, const std::string& bytes, int line, int column,
                        const std::string& words, const MeshLimits& limits = {}) {
    const auto path = write_file(name, bytes);
    const auto start = std::chrono::steady_clock::now();
    try {
        load_mesh_file(path, {}, limits);
    } catch (const SceneError& e) {
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_LT(seconds, 1.0) << name;
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << name << ": " << e.what();
        if (line < 0) {
            EXPECT_FALSE(e.position().file) << name << ": " << e.what();
            return e;
        }
        if (!e.position().file) {
            ADD_FAILURE() << name << ": no file in the error's position: " << e.what();
            return e;
        }
        EXPECT_EQ(e.position().file->path, path.string()) << e.what();
        EXPECT_EQ(e.position().line, line) << name << ": " << e.what();
        if (line > 0) {
            EXPECT_EQ(e.position().column, column) << name << ": " << e.what();
        }
        return e;
    }
    ADD_FAILURE() << "no error for " << name;
    return SceneError({}, "");
}

template <class T>
void put_le(std::string& out, T value) {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if (std::endian::native == std::endian::big) {
        std::reverse(raw, raw + sizeof(T));
    }
    out.append(reinterpret_cast<const char*>(raw), sizeof(T));
}

const std::string kXyz = "property float x\nproperty float y\nproperty float z\n";
const std::string kFaces = "element face 1\nproperty list uchar int vertex_indices\n";

std::string ascii_header(const std::string& elements) {
    return "ply\nformat ascii 1.0\n" + elements + "end_header\n";
}

// ---- PLY: elements ---------------------------------------------------------------------------------

TEST(PlyHostile, ASecondVertexElementIsAnErrorAtItsHeaderLine) {
    // Positions in one `vertex` element and normals in another: the normals' count would not be the
    // positions' (this used to read past the normals).
    const std::string header = ascii_header("element vertex 3\n" + kXyz +
                                            "element vertex 3\nproperty float nx\nproperty float ny\n"
                                            "property float nz\n" +
                                            kFaces);
    expect_error("two_vertex.ply", header + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 0 1\n0 0 1\n3 0 1 2\n", 7, 1,
                 "element 'vertex' is declared twice (first on line 3)");
    // The same split, binary: rejected from the header alone.
    expect_error("two_vertex_binary.ply",
                 "ply\nformat binary_little_endian 1.0\nelement vertex 1\n" + kXyz + "element vertex 1\n" +
                     kXyz + kFaces + "end_header\n" + std::string(100, '\0'),
                 7, 1, "declared twice");
}

TEST(PlyHostile, NormalsInAnotherElementAreIgnoredNotMisread) {
    const std::string text = ascii_header("element vertex 3\n" + kXyz +
                                          "element normal 3\nproperty float nx\nproperty float ny\n"
                                          "property float nz\n" +
                                          kFaces) +
                             "0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 0 1\n0 0 1\n3 0 1 2\n";
    const MeshData data = load_ply(write_file("normal_element.ply", text));
    EXPECT_EQ(data.positions.size(), 3u);
    EXPECT_TRUE(data.normals.empty());  // only the vertex element's nx, ny, nz are normals
    const Mesh mesh(data);
    EXPECT_NEAR(mesh.area(), 0.5, 1e-15);
}

TEST(PlyHostile, AnElementWithoutPropertiesCannotHaveRecords) {
    // It used to loop four billion times over nothing.
    for (const char* format : {"ascii", "binary_little_endian"}) {
        const std::string text = std::string("ply\nformat ") + format + " 1.0\nelement junk 4000000000\n" +
                                 "element vertex 3\n" + kXyz + kFaces + "end_header\n" + std::string(64, ' ');
        expect_error("junk.ply", text, 3, 1, "element 'junk' has 4000000000 records but no properties");
    }
    // None declared, none there: fine.
    const std::string empty_junk =
        ascii_header("element junk 0\nelement vertex 3\n" + kXyz + kFaces) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    EXPECT_EQ(load_ply(write_file("no_junk.ply", empty_junk)).triangles.size(), 1u);
}

TEST(PlyHostile, CountsMustFitInWhatFollowsTheHeader) {
    // Binary: 12 bytes at least per vertex (x, y, z floats) and 1 per face (its list's count).
    std::string binary =
        "ply\nformat binary_little_endian 1.0\nelement vertex 100000000\n" + kXyz + kFaces + "end_header\n";
    binary += std::string(40, '\0');
    expect_error("many_vertices.ply", binary, 3, 1,
                 "element 'vertex' declares 100000000 records of at least 12 bytes, but only 40 bytes");
    // The count that would fit alone, but not with the face after it.
    std::string tight = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + kXyz +
                        "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
    tight += std::string(36 + 1, '\0');
    expect_error("tight.ply", tight, 7, 1,
                 "element 'face' declares 2 records of at least 1 bytes, but only 1");
    // Ascii: a word and a blank per property at least (x y z: 3 words, 6 bytes).
    const std::string ascii =
        ascii_header("element vertex 50\n" + kXyz + kFaces) + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    expect_error("many_vertices_ascii.ply", ascii, 3, 1, "declares 50 records of at least 3 words");
    // 2^64 and more: not a count.
    expect_error("overflow.ply", ascii_header("element vertex 18446744073709551616\n" + kXyz), 3, 1,
                 "expected 'element <name> <count>'");
    expect_error("negative.ply", ascii_header("element vertex -1\n" + kXyz), 3, 1,
                 "expected 'element <name> <count>'");
}

TEST(PlyHostile, CountsBeyondTheLimitsAreErrorsBeforeReading) {
    // The default limit, 2^28 vertices, from a header alone (no data at all).
    expect_error("limit.ply", ascii_header("element vertex 268435457\n" + kXyz + kFaces), 3, 1,
                 "declares 268435457 vertices, more than the limit of 268435456 (2^28)");
    expect_error("face_limit.ply",
                 ascii_header("element vertex 3\n" + kXyz + "element face 268435457\n" +
                              "property list uchar int vertex_indices\n"),
                 7, 1, "declares 268435457 faces, more than the limit of 268435456 (2^28) triangles");
    // Smaller limits, as a caller may set them.
    MeshLimits limits;
    limits.max_vertices = 2;
    const std::string quad =
        ascii_header("element vertex 4\n" + kXyz + kFaces) + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
    expect_error("small_limit.ply", quad, 3, 1, "more than the limit of 2", limits);
    limits = {};
    limits.max_triangles = 1;  // the quad's fan makes two
    expect_error("triangle_limit.ply", quad, 14, 9, "makes more than 1 triangles", limits);
    limits = {};
    limits.max_file_bytes = 64;
    // About the file as a whole: positioned where the scene names the file (here: nowhere).
    expect_error("file_limit.ply", quad, -1, 0,
                 "is " + std::to_string(quad.size()) + " bytes, more than the limit of 64 bytes", limits);
}

// ---- PLY: header -----------------------------------------------------------------------------------

TEST(PlyHostile, MalformedHeadersArePositionedErrors) {
    expect_error("no_format.ply", "ply\nelement vertex 0\n" + kXyz + "end_header\n", 2, 1,
                 "no 'format' line");
    expect_error("unknown_type.ply", ascii_header("element vertex 1\nproperty quad x\n"), 4, 1,
                 "unknown property type 'quad'");
    expect_error(
        "list_of_lists.ply",
        ascii_header("element vertex 1\n" + kXyz + "element face 1\nproperty list uchar list int v\n"), 8, 1,
        "a list of lists");
    expect_error("float_count.ply",
                 ascii_header("element vertex 1\n" + kXyz + "element face 1\nproperty list float int v\n"), 8,
                 1, "non-integer list count type 'float'");
    expect_error("property_first.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n", 3, 1,
                 "a property before any element");
    expect_error("extra_word.ply", ascii_header("element vertex 3 4\n"), 3, 1, "unexpected '4'");
    expect_error("two_x.ply", ascii_header("element vertex 1\n" + kXyz + "property float x\n"), 7, 1,
                 "two properties named 'x'");
    expect_error("list_x.ply",
                 ascii_header("element vertex 1\nproperty list uchar float x\nproperty float y\n"
                              "property float z\n"),
                 3, 1, "no 'x' property (or it is a list)");
    expect_error("no_vertex.ply", ascii_header(kFaces), 1, 1, "no 'vertex' element");
}

// ---- PLY: data -------------------------------------------------------------------------------------

TEST(PlyHostile, HugeListLengthsAreErrorsAtTheirCount) {
    const std::string header =
        ascii_header("element vertex 3\n" + kXyz + "element face 1\nproperty list uint int vertex_indices\n");
    expect_error("huge_list.ply", header + "0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n", 13, 1,
                 "in face 0: a list of 4000000000 items runs past the end of the file");
    std::string binary = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" + kXyz +
                         "element face 1\nproperty list uint int vertex_indices\nend_header\n";
    const std::size_t face_at = binary.size() + 36;
    binary += std::string(36, '\0');
    put_le<std::uint32_t>(binary, 0xffffffffu);
    binary += std::string(12, '\0');
    expect_error("huge_list_binary.ply", binary, 0, 0,
                 "at byte " + std::to_string(face_at) + " (face 0): a list of 4294967295 items runs past");
    expect_error("short_face.ply", header + "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", 13, 1,
                 "a face needs at least three vertices, this one has 2");
}

TEST(PlyHostile, IndicesOutOfRangeAreErrorsAtTheIndex) {
    const std::string header = ascii_header("element vertex 3\n" + kXyz + kFaces);
    const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
    expect_error("negative.ply", header + vertices + "3 0 -1 2\n", 13, 5,
                 "in face 0: vertex index -1 is out of range (there are 3 vertices)");
    expect_error("large.ply", header + vertices + "3 0 1 4000000000\n", 13, 7, "vertex index 4000000000");
    expect_error("fraction.ply", header + vertices + "3 0 1 1.5\n", 13, 7,
                 "expected an integer, found '1.5'");
    // In a strip, −1 restarts; any other negative number is out of range.
    const std::string strips = ascii_header("element vertex 3\n" + kXyz +
                                            "element tristrips 1\nproperty list int int vertex_indices\n");
    expect_error("strip.ply", strips + vertices + "5 0 1 2 -1 -2\n", 13, 12,
                 "vertex index -2 is out of range");
}

TEST(PlyHostile, CoordinatesMustBeFiniteAndWithinFloatRange) {
    const std::string header = ascii_header("element vertex 3\n" + kXyz + kFaces);
    expect_error("nan.ply", header + "0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", 11, 3,
                 "in vertex 1: the vertex's y coordinate nan is not finite");
    expect_error("inf.ply", header + "0 0 0\n1 0 0\n0 1 -inf\n3 0 1 2\n", 12, 5,
                 "z coordinate -inf is not finite");
    expect_error("1e40.ply", header + "0 0 0\n1e40 0 0\n0 1 0\n3 0 1 2\n", 11, 1,
                 "in vertex 1: the vertex's x coordinate 1e+40 is beyond float's range");
    // Binary doubles: the error names the byte and the vertex index.
    std::string binary =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\n"
        "property double y\nproperty double z\n" +
        kFaces + "end_header\n";
    const double coordinates[9] = {0, 0, 0, 1, 0, 0, 0, 1e40, 0};
    for (double c : coordinates) {
        put_le<double>(binary, c);
    }
    const std::size_t y2_at = binary.size() - 16;
    put_le<std::uint8_t>(binary, 3);
    for (std::int32_t i : {0, 1, 2}) {
        put_le<std::int32_t>(binary, i);
    }
    expect_error(
        "1e40_binary.ply", binary, 0, 0,
        "at byte " + std::to_string(y2_at) + " (vertex 2): the vertex's y coordinate 1e+40 is beyond");
    // The largest float is still a coordinate.
    const std::string largest = header + "0 0 0\n3.4028234663852886e38 0 0\n0 1 0\n3 0 1 2\n";
    EXPECT_EQ(load_ply(write_file("largest.ply", largest)).positions[1].x, 3.4028234663852886e38);
}

// ---- OBJ -------------------------------------------------------------------------------------------

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST(ObjHostile, IndicesOutOfRangeAreErrorsAtTheCorner) {
    expect_error("huge_index.obj", kTriangle + "f 1 2 99999999999999999999\n", 4, 7,
                 "vertex index 99999999999999999999 is out of range (there are 3 vertices so far)");
    expect_error("big_index.obj", kTriangle + "f 1 2 4000000000\n", 4, 7,
                 "vertex index 4000000000 is out of range");
    expect_error("far_back.obj", kTriangle + "f 1 2 -99999999999999999999\n", 4, 7, "is out of range");
    expect_error("normal_index.obj", kTriangle + "vn 0 0 1\nf 1//1 2//1 3//2\n", 5, 13,
                 "normal index 2 is out of range (there are 1 normals so far)");
    expect_error("empty_index.obj", kTriangle + "f 1 2 /1\n", 4, 7, "expected a vertex index, found ''");
}

TEST(ObjHostile, CoordinatesMustBeFiniteAndWithinFloatRange) {
    expect_error("1e40.obj", "v 0 0 0\nv 1e40 0 0\n", 2, 3,
                 "the vertex coordinate 1e40 is beyond float's range (at most 3.4e38 in magnitude)");
    expect_error("-1e39.obj", "v 0 0 -1e39\n", 1, 7, "beyond float's range");
    expect_error("1e400.obj", "v 1e400 0 0\n", 1, 3, "the number '1e400' is out of range");
    expect_error("inf.obj", "v inf 0 0\n", 1, 3, "not finite");
    expect_error("nan_normal.obj", kTriangle + "vn 0 nan 1\n", 4, 6, "not finite");
    // A normal may be long (it is normalised) but not infinite.
    EXPECT_EQ(load_obj(write_file("long_normal.obj", kTriangle + "vn 0 0 1e300\nf 1//1 2//1 3//1\n"))
                  .normals.size(),
              3u);
}

TEST(ObjHostile, APolygonOfAMillionCornersIsAFanReadWithoutAListOfWords) {
    std::string face = "f";
    for (int i = 0; i < 1000000; ++i) {
        face += i % 2 == 0 ? " 1" : " 2";  // corners 1 2 1 2 …: every triangle is (1, 2, x)
    }
    face[face.size() - 1] = '3';
    const std::string text = kTriangle + face + "\n";
    const auto start = std::chrono::steady_clock::now();
    const MeshData mesh = load_obj(write_file("million.obj", text));
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
    EXPECT_EQ(mesh.triangles.size(), 1000000u - 2);
    EXPECT_EQ(mesh.positions.size(), 3u);  // corners that repeat share their vertex
    // With a limit of 1000 triangles: an error at the corner that makes the 1001st, corner 1002
    // (0-based), at column 2 + 2 · 1002 + 1; the quoted line is cut to a window around it.
    MeshLimits limits;
    limits.max_triangles = 1000;
    const SceneError e = expect_error("million_limited.obj", text, 4, 2007,
                                      "the OBJ file has more than 1000 triangles", limits);
    EXPECT_LT(std::string(e.what()).size(), 600u);
}

TEST(ObjHostile, VertexAndFileLimits) {
    MeshLimits limits;
    limits.max_vertices = 3;
    expect_error("vertices.obj", kTriangle + "v 1 1 1\n", 4, 1, "more than 3 vertex positions", limits);
    expect_error("normals.obj", kTriangle + "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n", 7, 1,
                 "more than 3 normals", limits);
    // Corners with different normals are different vertices: 4 of them from 3 positions.
    expect_error("corners.obj", kTriangle + "vn 0 0 1\nvn 0 0 -1\nf 1//1 2//1 3//1\nf 1//2 2//1 3//1\n", 7, 3,
                 "more than 3 vertices (distinct position, texture coordinate and normal triples)", limits);
    limits = {};
    limits.max_file_bytes = 16;
    expect_error("file.obj", kTriangle + "f 1 2 3\n", -1, 0, "more than the limit of 16 bytes", limits);
}

// ---- meshes made by code -------------------------------------------------------------------------

TEST(MeshFromCode, WhatIsNotAMeshIsAnErrorNotARead) {
    MeshData triangle;
    triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    triangle.triangles = {{0, 1, 2}};
    EXPECT_NO_THROW(Mesh{triangle});
    MeshData bad_index = triangle;
    bad_index.triangles.push_back({0, 1, 3});
    EXPECT_THROW(Mesh{bad_index}, std::invalid_argument);
    MeshData few_normals = triangle;
    few_normals.normals = {{0, 0, 1}};
    EXPECT_THROW(Mesh{few_normals}, std::invalid_argument);
    MeshData nan = triangle;
    nan.positions.push_back({0, kInf, 0});
    EXPECT_THROW(Mesh{nan}, std::invalid_argument);
}

}  // namespace
}  // namespace glint
