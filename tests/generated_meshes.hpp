// Meshes made by code, for tests and benchmarks that must not depend on data files (no GoogleTest here:
// bench/ includes this too).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "glint/core/math.hpp"
#include "glint/geometry/mesh_io/mesh_data.hpp"

namespace glint::test {

// A closed torus of exactly 2 · around · across triangles (a grid of quads that wraps both ways, its
// vertices shared), its tube's radius rippled so that it is bumpy as well as not convex; built in
// linear time, for meshes of millions of triangles.
inline MeshData displaced_torus(std::uint32_t around, std::uint32_t across) {
    MeshData mesh;
    mesh.positions.reserve(std::size_t{around} * across);
    for (std::uint32_t i = 0; i < around; ++i) {
        const double u = 2 * kPi * i / around;
        for (std::uint32_t j = 0; j < across; ++j) {
            const double v = 2 * kPi * j / across;
            const double tube =
                0.35 * (1 + 0.2 * std::sin(7 * u) * std::sin(3 * v) + 0.05 * std::sin(40 * u + 9 * v));
            const double ring = 1 + tube * std::cos(v);
            mesh.positions.push_back({ring * std::cos(u), tube * std::sin(v), ring * std::sin(u)});
        }
    }
    const auto vertex = [&](std::uint32_t i, std::uint32_t j) { return (i % around) * across + j % across; };
    mesh.triangles.reserve(2 * std::size_t{around} * across);
    for (std::uint32_t i = 0; i < around; ++i) {
        for (std::uint32_t j = 0; j < across; ++j) {
            mesh.triangles.push_back({vertex(i, j), vertex(i, j + 1), vertex(i + 1, j + 1)});
            mesh.triangles.push_back({vertex(i, j), vertex(i + 1, j + 1), vertex(i + 1, j)});
        }
    }
    return mesh;
}

// Writes `mesh` as a binary little-endian PLY file (float positions, int indices).
inline void write_binary_ply(const MeshData& mesh, const std::filesystem::path& path) {
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex " << mesh.positions.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << mesh.triangles.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    const auto put = [&](const auto value) {
        char bytes[sizeof(value)];
        std::memcpy(bytes, &value, sizeof(value));  // the machine is little-endian, as the format says
        out.write(bytes, sizeof(value));
    };
    for (const Vec3& p : mesh.positions) {
        put(static_cast<float>(p.x));
        put(static_cast<float>(p.y));
        put(static_cast<float>(p.z));
    }
    for (const auto& t : mesh.triangles) {
        put(std::uint8_t{3});
        for (const std::uint32_t i : t) {
            put(static_cast<std::int32_t>(i));
        }
    }
}

// A scene with a mesh of 262 144 triangles in a PLY file, for the preview's edits: what a camera or a
// material edit must not read or build again. Returns the scene's YAML; writes `torus.ply` to `dir`.
inline constexpr std::uint32_t kLargeMeshTriangles = 2 * 512 * 256;
inline std::string large_mesh_scene(const std::filesystem::path& dir) {
    write_binary_ply(displaced_torus(512, 256), dir / "torus.ply");
    return "render: {width: 64, height: 48, samples: 4}\n"
           "camera: {eye: [0, 2, 3], look_at: [0, 0, 0], fov: 50}\n"
           "materials: {clay: {type: matte, albedo: [0.7, 0.6, 0.5]}}\n"
           "objects: [{type: mesh, file: torus.ply, material: clay}]\n"
           "lights: [{type: point, position: [2, 4, 2], intensity: 20}]\n";
}

}  // namespace glint::test
