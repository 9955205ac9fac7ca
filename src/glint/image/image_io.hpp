// Reading and writing images. Writers are atomic: the bytes go to a temporary file beside the target,
// which is flushed to disk and renamed over it only once complete, so a crash or a full disk never leaves
// half an image under the user's name. Readers check every header against the limits below and against
// the file's length before they allocate anything from it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "glint/image/image.hpp"
#include "glint/image/png.hpp"
#include "glint/image/tone_map.hpp"

namespace glint {

// The largest image glint reads, whatever the format. A file that declares more is refused before
// anything is allocated from its header, so a tiny hostile file cannot ask for gigabytes.
// - kMaxImageSide: 32768 = 2¹⁵ pixels a side. The largest panoramas published for rendering are 16K × 8K
//   (16384 × 8192); this leaves room for twice that width.
// - kMaxImagePixels: 2²⁸ = 268 435 456 pixels (16384 × 16384). As linear float RGB that is already
//   3 GiB, about as much as a workstation can spend on one texture; stb_image's own int arithmetic also
//   stops near 2³¹ bytes (2²⁸ pixels of four 16-bit channels).
inline constexpr std::int64_t kMaxImageSide = 32768;
inline constexpr std::int64_t kMaxImagePixels = std::int64_t{1} << 28;
// An OpenEXR file is decoded with all its channels (a render's AOVs come along with R, G and B): its
// samples (channels × pixels, four bytes each once decoded) are limited to four channels at the pixel
// limit, 2³⁰ samples = 4 GiB.
inline constexpr std::int64_t kMaxExrSamples = 4 * kMaxImagePixels;
// A file is read into memory whole, once, so that the header checks and the decoder see the same bytes.
// 5 GiB is more than any image within the limits needs (an uncompressed EXR at kMaxExrSamples is 4 GiB
// plus its tables); a larger file is refused before it is read.
inline constexpr std::uint64_t kMaxImageFileBytes = std::uint64_t{5} << 30;

enum class ImageFormat { Png, Pfm, Exr };

// The format an output path asks for, by its extension (case-insensitive); nullopt if unknown.
std::optional<ImageFormat> image_format_for(const std::filesystem::path& path);
std::string supported_image_extensions();  // ".png, .pfm, .exr"

struct ImageWriteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Writes `image` (linear radiance) in the format of the path's extension:
// .png  8-bit sRGB after `display` (exposure and tone curve; by default values clamped to [0, 1]);
// .pfm  32-bit float linear RGB, exactly what the film holds (`display` is not applied);
// .exr  32-bit float linear RGB, exactly what the film holds (`display` is not applied).
void write_image(const Image& image, const std::filesystem::path& path, const DisplayTransform& display = {});

// Checks, before a render starts, that write_image(…, path) can succeed as far as the file system goes:
// throws ImageWriteError naming the path and the reason when the extension is unknown, the path is a
// folder, its folder is missing or is not a folder, the name is too long (NAME_MAX / PATH_MAX) or the
// folder is not writable. The last is tested by creating and removing a file there: permission bits
// do not tell (root ignores them; read-only mounts, ACLs and quotas are not in them).
void check_output_path(const std::filesystem::path& path);

// Extra header attributes of an OpenEXR file, name → text, written as OpenEXR "string" attributes
// (what `glint render --tile` records for `glint merge`; `exrheader` shows them).
using ExrAttributes = std::map<std::string, std::string>;

// Encoders into memory, for the atomic writer and for tests. encode_exr writes `attributes` into the
// header (a name of 1 to 255 bytes, a value not empty), and each of `layers` as channels named
// "layer.channel" beside R, G and B (OpenEXR's multi-layer convention: albedo.R, depth.Z; the AOVs);
// without either the bytes are as before.
std::vector<unsigned char> encode_png(const Image& image, const PngEncoding& encoding = kPngFileEncoding);
std::vector<unsigned char> encode_pfm(const Image& image);
// A layer of 3 channels as a colour PFM ("PF"), of 1 as a grey one ("Pf").
std::vector<unsigned char> encode_pfm(const ImageLayer& layer);
std::vector<unsigned char> encode_exr(const Image& image, const ExrAttributes& attributes = {},
                                      const std::vector<ImageLayer>& layers = {});

// Reads a PFM file: colour ("PF") as it is, grey ("Pf") with its value in all three channels. Throws
// std::runtime_error naming the file and what is wrong otherwise.
Image read_pfm(const std::filesystem::path& path);
// The same, from bytes already in memory; `name` is the file name used in error messages.
Image decode_pfm(const std::vector<unsigned char>& bytes, const std::string& name);

// Reads an image as linear RGB, choosing the decoder by the file's first bytes (not its extension):
// PNG, JPEG, BMP, TGA and binary PGM/PPM (8 or 16 bit, sRGB-decoded) and Radiance HDR through stb_image,
// OpenEXR through tinyexr and PFM (HDR, EXR and PFM already linear). Throws std::runtime_error, whose message
// names the file, when it is missing, unreadable, of another format, larger than the limits above or
// shorter than its header says. With `srgb` false, 8- and 16-bit samples are taken as they are (value /
// maximum), not sRGB-decoded: for images that hold data rather than colour (normal maps, glTF's
// metallic-roughness maps).
Image read_image(const std::filesystem::path& path, bool srgb = true);
// The same, from a file's bytes already in memory; `name` is the file name used in error messages.
Image decode_image(const std::vector<unsigned char>& bytes, const std::string& name, bool srgb = true);

// An OpenEXR file read with its header's "string" attributes (others are ignored).
struct ExrFile {
    Image image;
    ExrAttributes attributes;
};
// Reads an OpenEXR file as read_image does, with its string attributes; throws std::runtime_error naming
// the file when it is not an OpenEXR file or cannot be read.
ExrFile read_exr(const std::filesystem::path& path);

// The sRGB transfer function's inverse (IEC 61966-2-1): an encoded value in [0, 1] to linear.
double srgb_to_linear(double encoded);

// Writes bytes to `path` atomically: a temporary file in the same folder, written, fsync'ed, renamed
// over `path`, then the folder fsync'ed (best effort). Throws ImageWriteError on failure and leaves no
// temporary file behind.
void write_file_atomically(const std::filesystem::path& path, const std::vector<unsigned char>& bytes);

// Removes the temporary files being written at this moment (by write_file_atomically or
// check_output_path), for a SIGINT/SIGTERM handler: a process killed mid-write then leaves nothing
// behind. Async-signal-safe: it reads only lock-free atomics and fixed static buffers and calls only
// unlink(2). Never throws.
void remove_pending_temporary_files() noexcept;

namespace test_hooks {
// A test seam: when set, write_file_atomically calls it once the temporary file is complete and
// registered, just before the rename, with the temporary file's path.
extern void (*after_temporary_file_written)(const std::filesystem::path& temporary);
}  // namespace test_hooks

// Linear → sRGB-encoded byte, clamping to [0, 1].
unsigned char linear_to_srgb8(float linear);

}  // namespace glint
