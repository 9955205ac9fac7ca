// What the glTF tests share to write models in the test: base64 for data: URIs, the unit square.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>

#include "test_util.hpp"

namespace glint::test {

inline std::string base64(const std::string& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t n = (static_cast<unsigned char>(bytes[i]) << 16) |
                                (i + 1 < bytes.size() ? static_cast<unsigned char>(bytes[i + 1]) << 8 : 0) |
                                (i + 2 < bytes.size() ? static_cast<unsigned char>(bytes[i + 2]) : 0);
        out += alphabet[(n >> 18) & 63];
        out += alphabet[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? alphabet[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? alphabet[n & 63] : '=';
    }
    return out;
}

// The bytes of a unit square in the z = 0 plane (positions, then 16-bit indices), little-endian: 60
// bytes, the positions in the first 48 (unit_square_positions_accessor), the indices in the last 12.
inline std::string square_bytes() {
    const float positions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const std::uint16_t indices[] = {0, 1, 2, 0, 2, 3};
    std::string bytes(sizeof positions + sizeof indices, '\0');
    std::memcpy(bytes.data(), positions, sizeof positions);
    std::memcpy(bytes.data() + sizeof positions, indices, sizeof indices);
    return bytes;
}

// A .glb of the JSON `text`: header, the JSON chunk (padded with spaces) and the binary chunk (padded
// with zeros).
inline std::string glb(std::string text, std::string binary) {
    text.resize((text.size() + 3) / 4 * 4, ' ');
    binary.resize((binary.size() + 3) / 4 * 4, '\0');
    const auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    const auto total = static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + binary.size());
    return "glTF" + u32(2) + u32(total) + u32(static_cast<std::uint32_t>(text.size())) + "JSON" + text +
           u32(static_cast<std::uint32_t>(binary.size())) + std::string("BIN\0", 4) + binary;
}

// The accessor of the unit square's four corners, (0,0,0) (1,0,0) (1,1,0) (0,1,0), as floats in buffer
// view 0.
inline nlohmann::json unit_square_positions_accessor() {
    return {{"bufferView", 0}, {"componentType", 5126}, {"count", 4},
            {"type", "VEC3"},  {"min", {0, 0, 0}},      {"max", {1, 1, 0}}};
}

// `glint convert` of the model `model` in `dir` writes a YAML (in a folder below, so that its paths are
// rebased) that renders the same bits as the model.
inline void expect_convert_round_trip(const TempDir& dir, const std::string& model) {
    std::filesystem::create_directories(dir / "out");
    ASSERT_EQ(run_glint("convert '" + (dir / model).string() + "' -o '" +
                        (dir / "out/converted.yaml").string() + "'")
                  .exit_code,
              0);
    const std::string settings = " --width 24 --height 16 --spp 4 -q";
    ASSERT_EQ(
        run_glint("render '" + (dir / model).string() + "' -o '" + (dir / "a.pfm").string() + "'" + settings)
            .exit_code,
        0);
    ASSERT_EQ(run_glint("render '" + (dir / "out/converted.yaml").string() + "' -o '" +
                        (dir / "b.pfm").string() + "'" + settings)
                  .exit_code,
              0);
    const auto read = [](const std::filesystem::path& path) {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    EXPECT_FALSE(read(dir / "a.pfm").empty());
    EXPECT_EQ(read(dir / "a.pfm"), read(dir / "b.pfm"));
}

}  // namespace glint::test
