// The image readers' first line of defence: recognising a file's format by its first bytes and reading
// just enough of its header to check the declared size against glint's limits (image_io.hpp) and against
// what the file's length can hold, before any decoder allocates from that size. Internal to the image
// readers (image_read.cpp, pfm.cpp, exr.cpp); every function throws std::runtime_error whose message
// starts with the file's name.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "glint/image/image.hpp"
#include "glint/image/image_io.hpp"

namespace glint::image_detail {

// The whole of an image file, read once so that the header checks and the decoder see the same bytes.
// Throws, naming the file, when it is missing, not a regular file (a FIFO is not opened for reading:
// that could block), empty or larger than kMaxImageFileBytes.
std::vector<unsigned char> read_image_file(const std::filesystem::path& path);

// Decodes an OpenEXR file's R, G and B (or its single channel as grey) after checking its header
// (exr.cpp); its "string" attributes into `attributes` when given.
Image decode_exr(const unsigned char* data, std::size_t size, const std::string& name,
                 ExrAttributes* attributes = nullptr);

// Decodes a JPEG file through libjpeg-turbo after checking its declared size (jpeg.cpp).
Image decode_jpeg(const unsigned char* data, std::size_t size, const std::string& name, bool srgb = true);

enum class FileFormat { Png, Jpeg, Bmp, Tga, Pnm, Hdr, Exr, Pfm, Gif, Psd, Pic, Unknown };

// The format of a file from its first bytes. TGA has no signature: it is what remains when no other
// signature matches and the header is a plausible TGA one (as stb_image decides).
FileFormat sniff_format(const unsigned char* data, std::size_t size);
const char* format_name(FileFormat format);

// Throws unless 1 ≤ width, height ≤ kMaxImageSide and width × height ≤ kMaxImagePixels.
void check_declared_size(const std::string& name, const char* format, std::int64_t width,
                         std::int64_t height);

// Throws unless the file (`file_bytes` long) has at least `needed_bytes`, the fewest that can hold the
// declared width × height; `why` says where that number comes from (it ends the error message).
void check_file_holds(const std::string& name, const char* format, std::int64_t width, std::int64_t height,
                      std::uint64_t needed_bytes, std::uint64_t file_bytes, const std::string& why);

// What the checks of a file read by stb_image found: its size and how its samples are scaled.
struct StbHeader {
    std::int64_t width = 0;
    std::int64_t height = 0;
    int channels = 0;          // in the file: 1 grey, 2 grey + alpha, 3 RGB, 4 RGBA
    bool sixteen_bit = false;  // decode with stbi_load_16
    int max_value = 0;         // PNM only: the sample value that means 1 (255 and 65535 elsewhere)
};

// Checks the header of a PNG, JPEG, BMP, TGA, PNM or Radiance HDR file against the limits and against the
// file's length (compressed formats: against the most their coding can compress), and for HDR walks the
// run-length coded scanlines to make sure they end within the file (stb_image would otherwise loop
// forever on a truncated one). Cross-checks the size with stbi_info_from_memory, so that the decoder
// allocates exactly what was checked.
StbHeader check_stb_header(FileFormat format, const unsigned char* data, std::size_t size,
                           const std::string& name);

}  // namespace glint::image_detail
