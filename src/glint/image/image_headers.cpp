// Header checks for the formats stb_image decodes. Each parser reads only the fields it needs to bound the
// file: the declared size, and for uncompressed formats the bytes that size takes; for compressed ones
// the least their coding can spend on it (deflate: 1 bit per 258 bytes; TGA and HDR run-length packets:
// 128 and 127 pixels; JPEG, decoded by libjpeg-turbo, is checked in jpeg.cpp). The numbers are those of
// stb_image 2.27 (Debian's libstb), whose reading of each header the parsers follow and whose
// stbi_info_from_memory must agree.
#include "glint/image/image_headers.hpp"

#include <stb_image.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <stdexcept>
#include <string_view>

#include "glint/image/image_io.hpp"

namespace glint::image_detail {
namespace {

[[noreturn]] void fail(const std::string& name, const std::string& what) {
    throw std::runtime_error(name + ": " + what);
}

bool starts_with(const unsigned char* data, std::size_t size, std::string_view magic) {
    return size >= magic.size() && std::memcmp(data, magic.data(), magic.size()) == 0;
}

std::uint64_t ceil_div(std::uint64_t a, std::uint64_t b) {
    return a / b + (a % b != 0 ? 1 : 0);
}

// Bounds-checked reads of header fields: a header shorter than its fields is an error, not a read past
// the end of the file.
class HeaderBytes {
  public:
    HeaderBytes(const unsigned char* data, std::size_t size, const std::string& name, const char* format)
        : data_(data), size_(size), name_(name), format_(format) {}

    std::uint32_t u8(std::size_t at) const {
        need(at, 1);
        return data_[at];
    }
    std::uint32_t le16(std::size_t at) const {
        need(at, 2);
        return data_[at] | (std::uint32_t{data_[at + 1]} << 8);
    }
    std::uint32_t le32(std::size_t at) const {
        need(at, 4);
        return data_[at] | (std::uint32_t{data_[at + 1]} << 8) | (std::uint32_t{data_[at + 2]} << 16) |
               (std::uint32_t{data_[at + 3]} << 24);
    }
    std::uint32_t be32(std::size_t at) const {
        need(at, 4);
        return (std::uint32_t{data_[at]} << 24) | (std::uint32_t{data_[at + 1]} << 16) |
               (std::uint32_t{data_[at + 2]} << 8) | data_[at + 3];
    }
    bool has(std::size_t at, std::string_view text) const {
        return at <= size_ && text.size() <= size_ - at &&
               std::memcmp(data_ + at, text.data(), text.size()) == 0;
    }

  private:
    void need(std::size_t at, std::size_t n) const {
        if (at > size_ || n > size_ - at) {
            fail(name_, std::string(format_) + " header is truncated: the file has only " +
                            std::to_string(size_) + " bytes");
        }
    }
    const unsigned char* data_;
    std::size_t size_;
    const std::string& name_;
    const char* format_;
};

// A TGA header as stbi__tga_test accepts it: TGA files carry no signature.
bool plausible_tga(const unsigned char* data, std::size_t size) {
    if (size < 18) {
        return false;
    }
    const unsigned colormap_type = data[1], image_type = data[2];
    const auto in = [](unsigned v, std::initializer_list<unsigned> set) {
        return std::find(set.begin(), set.end(), v) != set.end();
    };
    if (colormap_type == 1) {
        if (!in(image_type, {1, 9}) || !in(data[7], {8, 15, 16, 24, 32}) || !in(data[16], {8, 16})) {
            return false;
        }
    } else if (colormap_type != 0 || !in(image_type, {2, 3, 10, 11}) || !in(data[16], {8, 15, 16, 24, 32})) {
        return false;
    }
    const unsigned width = data[12] | (data[13] << 8), height = data[14] | (data[15] << 8);
    return width >= 1 && height >= 1;
}

bool pnm_space(unsigned char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

// Binary PGM (P5) / PPM (P6): "P5 <width> <height> <maxval>" separated by whitespace and # comments, then
// one whitespace byte, then the samples: one or two bytes each (two when maxval > 255), uncompressed.
StbHeader check_pnm(const unsigned char* data, std::size_t size, const std::string& name,
                    std::uint64_t& needed, std::string& why) {
    StbHeader header;
    header.channels = data[1] == '6' ? 3 : 1;
    std::size_t at = 2;
    const auto skip_space_and_comments = [&] {
        for (;;) {
            while (at < size && pnm_space(data[at])) {
                ++at;
            }
            if (at >= size || data[at] != '#') {
                return;
            }
            while (at < size && data[at] != '\n' && data[at] != '\r') {
                ++at;
            }
        }
    };
    const auto number = [&](const char* what) {
        skip_space_and_comments();
        if (at >= size || data[at] < '0' || data[at] > '9') {
            fail(name,
                 std::string("PNM header has no ") + what + " (expected P5 or P6, width, height, maxval)");
        }
        std::int64_t value = 0;
        while (at < size && data[at] >= '0' && data[at] <= '9') {
            value = value * 10 + (data[at] - '0');
            if (value > INT_MAX) {
                fail(name, std::string("PNM header's ") + what + " has more digits than any image needs");
            }
            ++at;
        }
        return value;
    };
    header.width = number("width");
    header.height = number("height");
    const std::int64_t max_value = number("maxval");
    if (at >= size || !pnm_space(data[at])) {
        fail(name, "PNM header must end with one whitespace byte after maxval, before the samples");
    }
    ++at;
    if (max_value < 1 || max_value > 65535) {
        fail(name, "PNM maxval is " + std::to_string(max_value) + ", not in 1 ... 65535");
    }
    header.max_value = static_cast<int>(max_value);
    header.sixteen_bit = max_value > 255;
    check_declared_size(name, "PNM", header.width, header.height);
    const std::uint64_t sample_bytes = header.sixteen_bit ? 2 : 1;
    needed = at + static_cast<std::uint64_t>(header.width * header.height) * header.channels * sample_bytes;
    why = std::to_string(at) + " of header and " + std::to_string(header.channels) + " uncompressed " +
          std::to_string(8 * sample_bytes) + "-bit samples a pixel";
    return header;
}

// PNG: the IHDR chunk (after a CgBI chunk in Apple's variant) gives size, bit depth and colour type; the
// pixels, at least width × height × samples × depth bits, are deflated, which compresses at most 1032:1
// (a 258-byte match coded in 2 bits).
StbHeader check_png(const unsigned char* data, std::size_t size, const std::string& name,
                    std::uint64_t& needed, std::string& why) {
    const HeaderBytes bytes(data, size, name, "PNG");
    std::size_t chunk = 8;
    if (bytes.has(chunk + 4, "CgBI")) {
        chunk += 12 + std::size_t{bytes.be32(chunk)};
    }
    if (!bytes.has(chunk + 4, "IHDR") || bytes.be32(chunk) != 13) {
        fail(name, "PNG file does not start with an IHDR chunk");
    }
    StbHeader header;
    header.width = bytes.be32(chunk + 8);
    header.height = bytes.be32(chunk + 12);
    const std::uint32_t depth = bytes.u8(chunk + 16), colour_type = bytes.u8(chunk + 17);
    int samples = 0;
    switch (colour_type) {
        case 0:
            samples = 1;
            break;  // grey
        case 2:
            samples = 3;
            break;  // RGB
        case 3:
            samples = 1;
            break;  // palette index
        case 4:
            samples = 2;
            break;  // grey + alpha
        case 6:
            samples = 4;
            break;  // RGBA
        default:
            fail(name, "PNG colour type " + std::to_string(colour_type) + " is not one of 0, 2, 3, 4, 6");
    }
    if (depth != 1 && depth != 2 && depth != 4 && depth != 8 && depth != 16) {
        fail(name, "PNG bit depth " + std::to_string(depth) + " is not one of 1, 2, 4, 8, 16");
    }
    header.channels = colour_type == 3 ? 3 : samples;
    header.sixteen_bit = depth == 16;
    check_declared_size(name, "PNG", header.width, header.height);
    // stb_image grows its buffer to a chunk's declared length before it reads the chunk, so a 2 GiB
    // length in a 100-byte file would be allocated: every chunk up to IEND must lie within the file.
    for (std::size_t at = 8; at + 8 <= size;) {
        const std::uint64_t length = bytes.be32(at);
        const std::uint64_t end = at + 12 + length;  // length, type, data, CRC
        if (end > size) {
            std::string type(reinterpret_cast<const char*>(data + at + 4), 4);
            for (char& c : type) {
                c = c >= 0x20 && c < 0x7f ? c : '?';  // a hostile type may hold any byte
            }
            fail(name, "PNG chunk '" + type + "' at byte " + std::to_string(at) + " declares " +
                           std::to_string(length) + " bytes of data, but the file has " +
                           std::to_string(size) + " bytes");
        }
        if (bytes.has(at + 4, "IEND")) {
            break;
        }
        at = static_cast<std::size_t>(end);
    }
    const std::uint64_t pixel_bytes =
        ceil_div(static_cast<std::uint64_t>(header.width * header.height) * samples * depth, 8);
    needed = ceil_div(pixel_bytes, 1032);
    why = std::to_string(pixel_bytes) + " bytes of pixels, which deflate compresses at most 1032:1";
    return header;
}

// BMP: uncompressed rows (stb_image reads no RLE), each padded to 4 bytes, from the data offset on.
StbHeader check_bmp(const unsigned char* data, std::size_t size, const std::string& name,
                    std::uint64_t& needed, std::string& why) {
    const HeaderBytes bytes(data, size, name, "BMP");
    const std::uint64_t data_offset = bytes.le32(10);
    const std::uint32_t info_size = bytes.le32(14);
    StbHeader header;
    std::uint32_t bits = 0;
    if (info_size == 12) {  // OS/2 BITMAPCOREHEADER: 16-bit sizes
        header.width = bytes.le16(18);
        header.height = bytes.le16(20);
        bits = bytes.le16(24);
    } else if (info_size == 40 || info_size == 56 || info_size == 108 || info_size == 124) {
        header.width = static_cast<std::int32_t>(bytes.le32(18));
        // A negative height means rows stored top to bottom.
        const auto signed_height = static_cast<std::int32_t>(bytes.le32(22));
        header.height = signed_height < 0 ? -static_cast<std::int64_t>(signed_height) : signed_height;
        bits = bytes.le16(28);
        const std::uint32_t compression = bytes.le32(30);
        if (compression != 0 && compression != 3) {  // BI_RGB, BI_BITFIELDS
            fail(name, "BMP compression " + std::to_string(compression) +
                           " is not supported (only uncompressed BMP files are read)");
        }
    } else {
        fail(name, "BMP header size " + std::to_string(info_size) + " is not one of 12, 40, 56, 108, 124");
    }
    if (bits != 1 && bits != 4 && bits != 8 && bits != 16 && bits != 24 && bits != 32) {
        fail(name, "BMP has " + std::to_string(bits) + " bits a pixel, not 1, 4, 8, 16, 24 or 32");
    }
    if (data_offset < 14 + std::uint64_t{info_size}) {
        fail(name, "BMP pixel data offset " + std::to_string(data_offset) + " lies inside its header");
    }
    header.channels = 3;
    check_declared_size(name, "BMP", header.width, header.height);
    const auto w = static_cast<std::uint64_t>(header.width), h = static_cast<std::uint64_t>(header.height);
    const std::uint64_t row_stride = ceil_div(w * bits, 32) * 4;
    // The last row's padding may be missing: stb_image does not need it.
    needed = data_offset + row_stride * (h - 1) + ceil_div(w * bits, 8);
    why = "pixel data from byte " + std::to_string(data_offset) + ", " + std::to_string(bits) +
          " bits a pixel, rows padded to 4 bytes";
    return header;
}

// TGA: an 18-byte header, an image id, a palette when indexed, then pixels: uncompressed, or run-length
// packets of at most 128 pixels that cost at least a count byte and one pixel.
StbHeader check_tga(const unsigned char* data, std::size_t size, const std::string& name,
                    std::uint64_t& needed, std::string& why) {
    const HeaderBytes bytes(data, size, name, "TGA");
    const std::uint64_t id_length = bytes.u8(0);
    const bool indexed = bytes.u8(1) == 1;
    const bool run_length = bytes.u8(2) >= 9;
    const std::uint64_t palette_bytes = indexed ? bytes.le16(5) * ceil_div(bytes.u8(7), 8) : 0;
    StbHeader header;
    header.width = bytes.le16(12);
    header.height = bytes.le16(14);
    const std::uint64_t pixel_bytes = ceil_div(bytes.u8(16), 8);
    header.channels = 3;
    check_declared_size(name, "TGA", header.width, header.height);
    const auto pixels = static_cast<std::uint64_t>(header.width * header.height);
    const std::uint64_t start = 18 + id_length + palette_bytes;
    if (run_length) {
        needed = start + ceil_div(pixels, 128) * (1 + pixel_bytes);
        why = "run-length packets of at most 128 pixels, " + std::to_string(1 + pixel_bytes) +
              " bytes or more each";
    } else {
        needed = start + pixels * pixel_bytes;
        why = std::to_string(pixel_bytes) + " uncompressed bytes a pixel after " + std::to_string(start) +
              " bytes of header";
    }
    return header;
}

// Radiance HDR: text lines ("#?RADIANCE", variables, an empty line, "-Y <height> +X <width>"), then
// RGBE pixels. Returns the offset of the pixels.
std::size_t check_hdr_header(const unsigned char* data, std::size_t size, const std::string& name,
                             StbHeader& header) {
    std::size_t at = 0;
    const auto next_line = [&] {
        const auto* end = static_cast<const unsigned char*>(std::memchr(data + at, '\n', size - at));
        if (!end) {
            fail(name,
                 "Radiance HDR header is truncated (no end of line after byte " + std::to_string(at) + ")");
        }
        const std::string_view line(reinterpret_cast<const char*>(data + at),
                                    static_cast<std::size_t>(end - (data + at)));
        at = static_cast<std::size_t>(end - data) + 1;
        return line;
    };
    next_line();  // the signature, checked by sniff_format
    while (!next_line().empty()) {
    }
    // Parsed as stb_image does: "-Y ", a number, spaces, "+X ", a number.
    const std::string resolution(next_line().substr(0, 100));
    const auto unsupported = [&] {
        fail(name, "Radiance HDR resolution line is '" + resolution +
                       "'; glint reads only '-Y <height> +X <width>' (rows top to bottom)");
    };
    const char* p = resolution.c_str();
    char* end = nullptr;
    if (std::strncmp(p, "-Y ", 3) != 0) {
        unsupported();
    }
    errno = 0;
    const long long height = std::strtoll(p + 3, &end, 10);
    if (end == p + 3 || errno != 0) {
        unsupported();
    }
    p = end;
    while (*p == ' ') {
        ++p;
    }
    if (std::strncmp(p, "+X ", 3) != 0) {
        unsupported();
    }
    const long long width = std::strtoll(p + 3, &end, 10);
    if (end == p + 3 || errno != 0) {
        unsupported();
    }
    header.width = width;
    header.height = height;
    header.channels = 3;
    return at;
}

// Walks the pixels of a Radiance HDR file exactly as stb_image's decoder will and fails unless they end
// within the file: stb_image reads a missing byte as 0, a run-length count of 0 that never advances, so a
// truncated run-length scanline would make it loop forever.
void check_hdr_pixels(const unsigned char* data, std::size_t size, std::size_t at, const std::string& name,
                      const StbHeader& header) {
    const auto w = static_cast<std::uint64_t>(header.width), h = static_cast<std::uint64_t>(header.height);
    const auto flat = [&](std::uint64_t from, std::uint64_t pixels) {
        check_file_holds(name, "Radiance HDR", header.width, header.height, from + 4 * pixels, size,
                         "4 bytes a pixel, not run-length coded, from byte " + std::to_string(from));
    };
    if (w < 8 || w >= 32768) {  // stb_image reads these widths as flat pixels
        flat(at, w * h);
        return;
    }
    const auto truncated = [&](std::uint64_t row) {
        fail(name, "Radiance HDR pixel data ends in scanline " + std::to_string(row) + " of " +
                       std::to_string(h) + ": the file (" + std::to_string(size) + " bytes) is truncated");
    };
    for (std::uint64_t row = 0; row < h; ++row) {
        if (size - at < 4) {
            truncated(row);
        }
        if (data[at] != 2 || data[at + 1] != 2 || (data[at + 2] & 0x80) != 0) {
            // Not run-length coded: stb_image reads the whole image flat from this scanline's start.
            flat(at, w * h);
            return;
        }
        const std::uint64_t length = (std::uint64_t{data[at + 2]} << 8) | data[at + 3];
        if (length != w) {
            fail(name, "Radiance HDR scanline " + std::to_string(row) + " is " + std::to_string(length) +
                           " pixels long, not " + std::to_string(w));
        }
        at += 4;
        for (int component = 0; component < 4; ++component) {
            std::uint64_t x = 0;
            while (x < w) {
                if (at >= size) {
                    truncated(row);
                }
                std::uint64_t count = data[at++];
                const bool run = count > 128;  // a run: count − 128 copies of the next byte
                count = run ? count - 128 : count;
                if (count > w - x) {
                    fail(name, "Radiance HDR scanline " + std::to_string(row) + " has a run past its end");
                }
                const std::uint64_t payload = run ? 1 : count;
                if (size - at < payload) {
                    truncated(row);
                }
                at += payload;
                x += count;
            }
        }
    }
}

}  // namespace

FileFormat sniff_format(const unsigned char* data, std::size_t size) {
    if (starts_with(data, size, "\x89PNG\r\n\x1a\n")) {
        return FileFormat::Png;
    }
    if (starts_with(data, size, "\xff\xd8")) {
        return FileFormat::Jpeg;
    }
    if (starts_with(data, size, "BM")) {
        return FileFormat::Bmp;
    }
    if (starts_with(data, size, "\x76\x2f\x31\x01")) {
        return FileFormat::Exr;
    }
    if (starts_with(data, size, "#?RADIANCE\n") || starts_with(data, size, "#?RGBE\n")) {
        return FileFormat::Hdr;
    }
    if ((starts_with(data, size, "PF") || starts_with(data, size, "Pf")) && size > 2 && pnm_space(data[2])) {
        return FileFormat::Pfm;
    }
    if (starts_with(data, size, "P5") || starts_with(data, size, "P6")) {
        return FileFormat::Pnm;
    }
    if (starts_with(data, size, "GIF8")) {
        return FileFormat::Gif;
    }
    if (starts_with(data, size, "8BPS")) {
        return FileFormat::Psd;
    }
    if (starts_with(data, size, "\x53\x80\xf6\x34")) {
        return FileFormat::Pic;
    }
    return plausible_tga(data, size) ? FileFormat::Tga : FileFormat::Unknown;
}

const char* format_name(FileFormat format) {
    switch (format) {
        case FileFormat::Png:
            return "PNG";
        case FileFormat::Jpeg:
            return "JPEG";
        case FileFormat::Bmp:
            return "BMP";
        case FileFormat::Tga:
            return "TGA";
        case FileFormat::Pnm:
            return "PNM";
        case FileFormat::Hdr:
            return "Radiance HDR";
        case FileFormat::Exr:
            return "OpenEXR";
        case FileFormat::Pfm:
            return "PFM";
        case FileFormat::Gif:
            return "GIF";
        case FileFormat::Psd:
            return "PSD";
        case FileFormat::Pic:
            return "Softimage PIC";
        case FileFormat::Unknown:
            break;
    }
    return "unknown";
}

void check_declared_size(const std::string& name, const char* format, std::int64_t width,
                         std::int64_t height) {
    const std::string declared = std::string(format) + " header declares " + std::to_string(width) + " x " +
                                 std::to_string(height) + " pixels";
    if (width < 1 || height < 1) {
        fail(name, declared + "; an image needs at least one pixel a side");
    }
    if (width > kMaxImageSide || height > kMaxImageSide || width * height > kMaxImagePixels) {
        fail(name, declared + ", more than glint reads: at most " + std::to_string(kMaxImageSide) +
                       " pixels a side and " + std::to_string(kMaxImagePixels) + " pixels in all");
    }
}

void check_file_holds(const std::string& name, const char* format, std::int64_t width, std::int64_t height,
                      std::uint64_t needed_bytes, std::uint64_t file_bytes, const std::string& why) {
    if (needed_bytes > file_bytes) {
        fail(name, std::string(format) + " header declares " + std::to_string(width) + " x " +
                       std::to_string(height) + " pixels, which need at least " +
                       std::to_string(needed_bytes) + " bytes (" + why + "), but the file has " +
                       std::to_string(file_bytes) + " bytes: it is truncated or corrupt");
    }
}

StbHeader check_stb_header(FileFormat format, const unsigned char* data, std::size_t size,
                           const std::string& name) {
    const char* format_text = format_name(format);
    if (size > static_cast<std::size_t>(INT_MAX)) {  // stb_image takes a length as an int
        fail(name, std::string(format_text) + " file has " + std::to_string(size) +
                       " bytes, more than the 2 GiB stb_image reads");
    }
    StbHeader header;
    std::uint64_t needed = 0;
    std::string why;
    std::size_t hdr_pixels_at = 0;
    switch (format) {
        case FileFormat::Png:
            header = check_png(data, size, name, needed, why);
            break;
        case FileFormat::Bmp:
            header = check_bmp(data, size, name, needed, why);
            break;
        case FileFormat::Tga:
            header = check_tga(data, size, name, needed, why);
            break;
        case FileFormat::Pnm:
            header = check_pnm(data, size, name, needed, why);
            break;
        case FileFormat::Hdr:
            hdr_pixels_at = check_hdr_header(data, size, name, header);
            check_declared_size(name, format_text, header.width, header.height);
            break;
        default:
            fail(name, std::string(format_text) + " is not decoded through stb_image");
    }
    int info_width = 0, info_height = 0, info_channels = 0;
    if (!stbi_info_from_memory(data, static_cast<int>(size), &info_width, &info_height, &info_channels)) {
        const char* reason = stbi_failure_reason();
        fail(name, std::string("not a readable ") + format_text + " file (" +
                       (reason ? reason : "no reason given") + ")");
    }
    if (info_width != header.width || info_height != header.height) {
        fail(name, std::string(format_text) + " header read two ways: " + std::to_string(header.width) +
                       " x " + std::to_string(header.height) + " by glint's check, " +
                       std::to_string(info_width) + " x " + std::to_string(info_height) + " by stb_image");
    }
    if (format == FileFormat::Hdr) {
        check_hdr_pixels(data, size, hdr_pixels_at, name, header);
    } else {
        check_file_holds(name, format_text, header.width, header.height, needed, size, why);
    }
    return header;
}

}  // namespace glint::image_detail
