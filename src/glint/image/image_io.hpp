// Reading and writing images. Writers are atomic: the bytes go to a temporary file beside the target,
// which is renamed over it only once complete, so a crash or a full disk never leaves half an image
// under the user's name.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "glint/image/image.hpp"

namespace glint {

enum class ImageFormat { Png, Pfm, Exr };

// The format an output path asks for, by its extension (case-insensitive); nullopt if unknown.
std::optional<ImageFormat> image_format_for(const std::filesystem::path& path);
std::string supported_image_extensions();  // ".png, .pfm, .exr"

struct ImageWriteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Writes `image` (linear radiance) in the format of the path's extension:
// .png  8-bit sRGB, values clamped to [0, 1] (the only tone mapping for now);
// .pfm  32-bit float linear RGB, exactly what the film holds;
// .exr  32-bit float linear RGB, exactly what the film holds.
void write_image(const Image& image, const std::filesystem::path& path);

// Encoders into memory, for the atomic writer and for tests.
std::vector<unsigned char> encode_png(const Image& image);
std::vector<unsigned char> encode_pfm(const Image& image);
std::vector<unsigned char> encode_exr(const Image& image);

// Reads a PFM written by encode_pfm (or any 3-channel PFM); throws std::runtime_error otherwise.
Image read_pfm(const std::filesystem::path& path);

// Reads an image as linear RGB: PNG, JPEG, BMP, TGA (8 or 16 bit, sRGB-decoded) and Radiance HDR through
// stb_image, OpenEXR through tinyexr and PFM (all three already linear). Throws std::runtime_error with
// the reason when the file is missing or unreadable.
Image read_image(const std::filesystem::path& path);

// The sRGB transfer function's inverse (IEC 61966-2-1): an encoded value in [0, 1] to linear.
double srgb_to_linear(double encoded);

// Writes bytes to `path` atomically (temporary file + rename).
void write_file_atomically(const std::filesystem::path& path, const std::vector<unsigned char>& bytes);

// Linear → sRGB-encoded byte, clamping to [0, 1].
unsigned char linear_to_srgb8(float linear);

}  // namespace glint
