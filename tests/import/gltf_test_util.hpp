// What the glTF tests share to write models in the test: base64 for data: URIs, the unit square.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

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

// The accessor of the unit square's four corners, (0,0,0) (1,0,0) (1,1,0) (0,1,0), as floats in buffer
// view 0.
inline nlohmann::json unit_square_positions_accessor() {
    return {{"bufferView", 0}, {"componentType", 5126}, {"count", 4},
            {"type", "VEC3"},  {"min", {0, 0, 0}},      {"max", {1, 1, 0}}};
}

}  // namespace glint::test
