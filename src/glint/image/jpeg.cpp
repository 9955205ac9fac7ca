// JPEG through libjpeg-turbo rather than stb_image. stb_image 2.27 (Debian 12's) reads corrupt
// entropy-coded data with undefined shifts and an index millions of bytes past a 256-entry table
// (found by fuzz/image_jpeg; fixed upstream only in part); libjpeg-turbo is the decoder that
// OSS-Fuzz has been fuzzing for years, and it treats a corrupt file as an error or a warning.
//
// libjpeg reports a fatal error by calling error_exit, which must not return: it longjmps back to
// decode_jpeg_pixels, a function that holds no C++ object with a destructor across the setjmp, so
// nothing is skipped. Warnings (corrupt data that libjpeg would paper over with grey) are errors here
// too: a texture that decodes to something other than the file's picture is a silent wrong image.
#include <array>
#include <csetjmp>
#include <cstddef>
#include <cstdio>  // before jpeglib.h, which uses size_t and FILE without including their headers
#include <cstring>
#include <stdexcept>

#include <jpeglib.h>

#include "glint/image/image_headers.hpp"
#include "glint/image/image_io.hpp"

namespace glint::image_detail {
namespace {

// A progressive JPEG may hold any number of scans, each a pass over every block of a component: a file
// of a few kilobytes with thousands of empty scans would take minutes. Real encoders write at most a
// few dozen (libjpeg's own progressive script writes 10); libjpeg-turbo's fuzzers stop at 500, as here.
constexpr int kMaxJpegScans = 500;

struct ErrorManager {
    jpeg_error_mgr base;  // first, so that a j_common_ptr's err is also an ErrorManager*
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

void on_error(j_common_ptr info) {
    auto* errors = reinterpret_cast<ErrorManager*>(info->err);
    errors->base.format_message(info, errors->message);
    std::longjmp(errors->jump, 1);
}

void on_message(j_common_ptr info, int level) {
    if (level < 0) {  // a warning: corrupt data
        on_error(info);
    }
}

void on_progress(j_common_ptr info) {
    const auto* decompress = reinterpret_cast<j_decompress_ptr>(info);
    if (decompress->input_scan_number > kMaxJpegScans) {
        auto* errors = reinterpret_cast<ErrorManager*>(info->err);
        std::snprintf(errors->message, sizeof errors->message, "more than %d scans", kMaxJpegScans);
        std::longjmp(errors->jump, 1);
    }
}

// The size in the frame header (SOF0 to SOF15), found by walking the marker segments before it; false
// when there is none before the first scan. Read before libjpeg, so that a file that declares a
// size it cannot hold is refused as such, even when it ends right after its frame header.
bool read_frame_size(const unsigned char* data, std::size_t size, long& width, long& height) {
    std::size_t at = 2;  // after the start of image, FF D8
    while (at + 1 < size) {
        if (data[at] != 0xff) {
            return false;  // libjpeg resynchronises on stray bytes; leave the file to it
        }
        const unsigned marker = data[at + 1];
        if (marker == 0xff) {  // a fill byte before a marker
            ++at;
            continue;
        }
        at += 2;
        if (marker == 0xda || marker == 0xd9 || at + 1 >= size) {  // a scan or the end before a frame
            return false;
        }
        const bool frame = marker >= 0xc0 && marker <= 0xcf && marker != 0xc4 && marker != 0xc8 &&
                           marker != 0xcc;  // DHT, JPG and DAC share the range
        if (frame) {
            if (at + 7 > size) {
                return false;
            }
            height = (static_cast<long>(data[at + 3]) << 8) | data[at + 4];
            width = (static_cast<long>(data[at + 5]) << 8) | data[at + 6];
            return true;
        }
        at += (static_cast<std::size_t>(data[at]) << 8) | data[at + 1];
    }
    return false;
}

// What the header says, and how far the decoder got. Filled through a reference: a local of the
// function that calls setjmp, changed after it, would be indeterminate after the longjmp.
struct JpegResult {
    bool ok = false;
    bool header_read = false;
    long width = 0, height = 0;
};

// The decoding itself, with libjpeg's C interface only: on a fatal error on_error longjmps to the
// setjmp here, and every libjpeg allocation is released by jpeg_destroy_decompress. `check_header` is
// called once the size is known and before anything is allocated from it; it returns false to stop.
// `rows` receives the decoded samples: three (RGB) or four (CMYK) a pixel, row after row.
template <typename CheckHeader, typename Rows>
void decode_jpeg_pixels(const unsigned char* data, std::size_t size, ErrorManager& errors,
                        CheckHeader&& check_header, Rows&& rows, JpegResult& result) {
    jpeg_decompress_struct info;
    std::memset(&info, 0, sizeof info);
    info.err = jpeg_std_error(&errors.base);
    errors.base.error_exit = on_error;
    errors.base.emit_message = on_message;
    jpeg_progress_mgr progress;
    std::memset(&progress, 0, sizeof progress);
    progress.progress_monitor = on_progress;
    if (setjmp(errors.jump)) {
        jpeg_destroy_decompress(&info);
        return;
    }
    jpeg_create_decompress(&info);
    info.progress = &progress;
    jpeg_mem_src(&info, data, static_cast<unsigned long>(size));
    jpeg_read_header(&info, TRUE);
    result.header_read = true;
    result.width = static_cast<long>(info.image_width);
    result.height = static_cast<long>(info.image_height);
    if (!check_header(result.width, result.height)) {
        jpeg_destroy_decompress(&info);
        return;
    }
    // CMYK and YCCK (Adobe's) cannot be converted to RGB by libjpeg; they are decoded as CMYK.
    const bool cmyk = info.jpeg_color_space == JCS_CMYK || info.jpeg_color_space == JCS_YCCK;
    info.out_color_space = cmyk ? JCS_CMYK : JCS_RGB;
    jpeg_start_decompress(&info);
    const bool inverted = cmyk && info.saw_Adobe_marker;  // Photoshop writes CMYK inverted
    while (info.output_scanline < info.output_height) {
        unsigned char* row = rows(static_cast<long>(info.output_scanline));
        jpeg_read_scanlines(&info, &row, 1);
    }
    jpeg_finish_decompress(&info);
    jpeg_destroy_decompress(&info);
    rows.finish(cmyk, inverted);
    result.ok = true;
}

}  // namespace

Image decode_jpeg(const unsigned char* data, std::size_t size, const std::string& name, bool srgb) {
    const std::string prefix = name + ": ";
    std::string header_error;
    const auto check_header = [&](long width, long height) {
        try {
            check_declared_size(name, "JPEG", width, height);
            // Every 8 × 8 block of every component costs at least one bit (a Huffman code is 1 to 16
            // bits; baseline blocks need two, progressive ones one in the first DC scan). Subsampled
            // components have fewer blocks, but sampling factors of at most 4 leave the components
            // together at least half a block for each 64 pixels (4 × 1 and 1 × 4 is the worst): 1 bit
            // per 128 pixels.
            const auto pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
            check_file_holds(name, "JPEG", width, height, (pixels + 1023) / 1024, size,
                             "at least 1 bit for every 128 pixels");
        } catch (const std::runtime_error& error) {
            header_error = error.what();
            return false;
        }
        return true;
    };
    // The samples go into a buffer of four bytes a pixel, the most the decoder writes.
    struct Rows {
        std::vector<unsigned char> samples;
        long width = 0;
        bool cmyk = false, inverted = false;
        unsigned char* operator()(long row) {
            if (samples.empty()) {
                return nullptr;
            }
            return samples.data() + static_cast<std::size_t>(row) * static_cast<std::size_t>(width) * 4;
        }
        void finish(bool is_cmyk, bool is_inverted) {
            cmyk = is_cmyk;
            inverted = is_inverted;
        }
    } rows;
    if (long width = 0, height = 0;
        read_frame_size(data, size, width, height) && !check_header(width, height)) {
        throw std::runtime_error(header_error);
    }
    ErrorManager errors{};
    // Called between libjpeg's calls, never from inside one: an exception here does not cross C frames.
    const auto checked = [&](long width, long height) {
        if (!check_header(width, height)) {
            return false;
        }
        rows.width = width;
        rows.samples.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
        return true;
    };
    JpegResult result;
    decode_jpeg_pixels(data, size, errors, checked, rows, result);
    if (!header_error.empty()) {
        throw std::runtime_error(header_error);
    }
    if (!result.ok) {
        throw std::runtime_error(
            prefix + (result.header_read ? "cannot decode the JPEG file (" : "not a readable JPEG file (") +
            errors.message + ")");
    }
    // 8-bit sRGB to linear (or, for data such as normal maps, the plain value), once per value.
    std::array<float, 256> linear{};
    for (int v = 0; v < 256; ++v) {
        linear[static_cast<std::size_t>(v)] =
            static_cast<float>(srgb ? srgb_to_linear(v / 255.0) : v / 255.0);
    }
    Image image(static_cast<int>(result.width), static_cast<int>(result.height));
    const std::size_t stride = rows.cmyk ? 4 : 3;
    for (std::size_t row = 0; row < static_cast<std::size_t>(result.height); ++row) {
        const unsigned char* in = rows.samples.data() + row * static_cast<std::size_t>(result.width) * 4;
        for (std::size_t x = 0; x < static_cast<std::size_t>(result.width); ++x) {
            const std::size_t i = row * static_cast<std::size_t>(result.width) + x;
            const unsigned char* pixel = in + x * stride;
            for (std::size_t c = 0; c < 3; ++c) {
                unsigned value = pixel[c];
                if (rows.cmyk) {
                    // RGB = (1 − C)(1 − K); an inverted (Adobe) file stores 1 − C and 1 − K.
                    const unsigned ink = rows.inverted ? pixel[c] : 255u - pixel[c];
                    const unsigned key = rows.inverted ? pixel[3] : 255u - pixel[3];
                    value = (ink * key + 127) / 255;
                }
                image.rgb[3 * i + c] = linear[value];
            }
        }
    }
    return image;
}

}  // namespace glint::image_detail
