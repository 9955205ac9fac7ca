// PNG encoding: glint's own writer on zlib, after the PNG specification (W3C, second edition; ISO/IEC
// 15948): the signature, IHDR (8-bit RGB, not interlaced), the filtered rows deflated by zlib in IDAT
// chunks, and IEND; each chunk's CRC is zlib's crc32, which is the CRC the specification defines.
//
// Why not stb_image_write, which glint used before (and still uses to decode): its deflate writes fixed
// Huffman codes only, so the noisy frames of a progressive render, whose filtered bytes are spread over
// many values, compress poorly. The default PngEncoding (png.hpp), each row with the filter of smallest
// sum of absolute values and zlib's run-length deflate (Z_RLE), was chosen by re-encoding the frames
// `glint serve` sent from 1 to 256 spp (bytes a frame; CPU milliseconds a frame, one thread):
//
//                                  Cornell box 512x512     lights.yaml 640x360    lights.yaml 1280x720
//   stb_image_write (level 8)      501 385 B   35.5 ms     282 297 B   26.5 ms    1 087 758 B  109 ms
//   this, smallest sum + Z_RLE     334 748 B    6.4 ms     205 691 B    5.4 ms      786 552 B   21 ms
//   this, smallest sum + level 6   348 311 B   47 ms       191 018 B   35 ms        725 153 B  139 ms
//   this, smallest sum + level 9   345 064 B  142 ms       184 252 B  329 ms
//
// (The Cornell box at 1280x720 from 1 to 64 spp: 1 139 050 B in 77.5 ms with stb, 782 913 B in 14.7 ms
// here.) Run-length deflate looks for repeats at distance 1 only, which is what filtered noise offers:
// in a fifth of stb's time it makes frames 27 to 33 % smaller than stb did; the default strategy at
// level 6 or 9 gains at most a tenth more (lights.yaml) or loses (the Cornell box), in 6 to 60 times the
// time. One sample per pixel at 1280x720 costs about half a second of CPU for these scenes, so the
// preview's encode, once a pass, went from about a fifth of that to about a twentieth. (CPU times on a
// shared, loaded machine: their ratios are the figure, not their values.) The filters, with Z_RLE, in
// bytes a frame for the two small scenes:
// None 611 218 / 364 538, Sub 359 439 / 212 103, Up 352 971 / 218 541, Average 348 548 / 213 839,
// Paeth 351 000 / 212 328, smallest sum 334 748 / 205 691: no one filter for the whole image beats the
// per-row choice (at level 6 None and Sub do for lights.yaml's flat sky, 172 863 and 175 443 B, but not
// for the Cornell box, 423 214 and 358 574 B). Measured on Debian 12's zlib 1.2.13.
//
// Files are another matter (kPngFileEncoding): a finished picture is often smooth, where run-length
// deflate does worst. Re-encoding the 27 pictures of docs/gallery/ (bytes in all; milliseconds in all):
// Z_RLE 1 600 361 B in 77 ms, default level 6 1 502 996 B in 215 ms, Z_FILTERED level 6 1 465 513 B in
// 239 ms, Z_FILTERED level 4 1 523 880 B in 124 ms; umbra-penumbra alone 24 368 B with Z_RLE and 10 622 B
// filtered. A file is written once, so the smallest for 9 ms more a picture. (Noisy frames, filtered at
// level 6: 4 % more bytes than Z_RLE in 4 times its time, so frames keep Z_RLE.)
#include "glint/image/png.hpp"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "glint/image/image_io.hpp"

namespace glint {
namespace {

constexpr std::size_t kBytesPerPixel = 3;  // 8-bit R, G, B
// IDAT chunks are cut at this length; a chunk may hold up to 2³¹ − 1 bytes, and decoders join them.
constexpr std::size_t kMaxIdatBytes = std::size_t{1} << 30;

void append_be32(std::vector<unsigned char>& out, std::uint32_t value) {
    for (int shift = 24; shift >= 0; shift -= 8) {
        out.push_back(static_cast<unsigned char>(value >> shift));
    }
}

// A chunk: its data's length, its type, the data, and the CRC of type and data.
void append_chunk(std::vector<unsigned char>& out, const char (&type)[5], const unsigned char* data,
                  std::size_t size) {
    append_be32(out, static_cast<std::uint32_t>(size));
    const auto* type_bytes = reinterpret_cast<const unsigned char*>(type);
    out.insert(out.end(), type_bytes, type_bytes + 4);
    out.insert(out.end(), data, data + size);
    uLong crc = crc32_z(0, type_bytes, 4);
    if (size > 0) {  // crc32_z of a null buffer would return the initial value, not leave crc alone
        crc = crc32_z(crc, data, size);
    }
    append_be32(out, static_cast<std::uint32_t>(crc));
}

unsigned char paeth_predictor(int left, int above, int above_left) {
    const int estimate = left + above - above_left;
    const int to_left = std::abs(estimate - left);
    const int to_above = std::abs(estimate - above);
    const int to_above_left = std::abs(estimate - above_left);
    if (to_left <= to_above && to_left <= to_above_left) {
        return static_cast<unsigned char>(left);
    }
    return static_cast<unsigned char>(to_above <= to_above_left ? above : above_left);
}

// Writes the filter's type byte and the filtered row into `out` (1 + row.size() bytes). `above` is the
// previous row, all zeros for the first (as the specification says).
void filter_row(PngRowFilter filter, std::span<const unsigned char> row, std::span<const unsigned char> above,
                unsigned char* out) {
    out[0] = static_cast<unsigned char>(filter);
    unsigned char* filtered = out + 1;
    const std::size_t size = row.size();
    const auto left_of = [&](std::size_t i) -> int {
        return i >= kBytesPerPixel ? row[i - kBytesPerPixel] : 0;
    };
    const auto above_left_of = [&](std::size_t i) -> int {
        return i >= kBytesPerPixel ? above[i - kBytesPerPixel] : 0;
    };
    switch (filter) {
        case PngRowFilter::None:
            std::copy(row.begin(), row.end(), filtered);
            break;
        case PngRowFilter::Sub:
            for (std::size_t i = 0; i < size; ++i) {
                filtered[i] = static_cast<unsigned char>(row[i] - left_of(i));
            }
            break;
        case PngRowFilter::Up:
            for (std::size_t i = 0; i < size; ++i) {
                filtered[i] = static_cast<unsigned char>(row[i] - above[i]);
            }
            break;
        case PngRowFilter::Average:
            for (std::size_t i = 0; i < size; ++i) {
                filtered[i] = static_cast<unsigned char>(row[i] - (left_of(i) + above[i]) / 2);
            }
            break;
        case PngRowFilter::Paeth:
            for (std::size_t i = 0; i < size; ++i) {
                filtered[i] = static_cast<unsigned char>(
                    row[i] - paeth_predictor(left_of(i), above[i], above_left_of(i)));
            }
            break;
        case PngRowFilter::SmallestSum:
            break;  // chosen by the caller, never written as such
    }
}

std::uint64_t sum_of_absolute_signed(const unsigned char* bytes, std::size_t size) {
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < size; ++i) {
        sum += static_cast<std::uint64_t>(std::abs(static_cast<int>(static_cast<signed char>(bytes[i]))));
    }
    return sum;
}

int zlib_strategy(PngDeflateStrategy strategy) {
    switch (strategy) {
        case PngDeflateStrategy::Filtered:
            return Z_FILTERED;
        case PngDeflateStrategy::Rle:
            return Z_RLE;
        case PngDeflateStrategy::HuffmanOnly:
            return Z_HUFFMAN_ONLY;
        case PngDeflateStrategy::Default:
            break;
    }
    return Z_DEFAULT_STRATEGY;
}

// Deflates the filtered rows one by one (zlib format, as IDAT holds), so that the filtered image is
// never held whole.
class RowDeflater {
  public:
    RowDeflater(const PngEncoding& encoding, std::size_t total_input) {
        if (encoding.level < 1 || encoding.level > 9) {
            throw ImageWriteError("PNG encoding: zlib level " + std::to_string(encoding.level) +
                                  " is not 1 to 9");
        }
        if (deflateInit2(&stream_, encoding.level, Z_DEFLATED, 15, 8, zlib_strategy(encoding.strategy)) !=
            Z_OK) {
            throw ImageWriteError("PNG encoding: zlib could not start");
        }
        output_.resize(deflateBound(&stream_, total_input));
    }
    ~RowDeflater() { deflateEnd(&stream_); }
    RowDeflater(const RowDeflater&) = delete;
    RowDeflater& operator=(const RowDeflater&) = delete;

    void add(const unsigned char* bytes, std::size_t size, bool last) {
        stream_.next_in = const_cast<unsigned char*>(bytes);  // zlib's API is not const; it only reads
        stream_.avail_in = static_cast<uInt>(size);
        const int flush = last ? Z_FINISH : Z_NO_FLUSH;
        for (;;) {
            if (used_ == output_.size()) {
                output_.resize(output_.size() * 2);
            }
            const std::size_t room = std::min<std::size_t>(output_.size() - used_, UINT_MAX);
            stream_.next_out = output_.data() + used_;
            stream_.avail_out = static_cast<uInt>(room);
            const int status = deflate(&stream_, flush);
            used_ += room - stream_.avail_out;
            if (status == Z_STREAM_END) {
                return;
            }
            if (status != Z_OK && status != Z_BUF_ERROR) {
                throw ImageWriteError("PNG encoding: zlib failed");
            }
            if (!last && stream_.avail_in == 0) {
                return;
            }
        }
    }

    std::span<const unsigned char> compressed() const { return {output_.data(), used_}; }

  private:
    z_stream stream_{};
    std::vector<unsigned char> output_;
    std::size_t used_ = 0;
};

}  // namespace

std::vector<unsigned char> encode_png_rgb8(std::span<const unsigned char> rgb, int width, int height,
                                           const PngEncoding& encoding) {
    if (width < 1 || height < 1 ||
        rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * kBytesPerPixel) {
        throw ImageWriteError("PNG encoding: " + std::to_string(width) + " x " + std::to_string(height) +
                              " pixels do not match " + std::to_string(rgb.size()) + " bytes of RGB");
    }
    const std::size_t stride = static_cast<std::size_t>(width) * kBytesPerPixel;
    RowDeflater deflater(encoding, (stride + 1) * static_cast<std::size_t>(height));

    const std::vector<unsigned char> zero_row(stride, 0);
    constexpr std::array kFilters = {PngRowFilter::None, PngRowFilter::Sub, PngRowFilter::Up,
                                     PngRowFilter::Average, PngRowFilter::Paeth};
    std::vector<unsigned char> chosen(stride + 1);
    std::vector<unsigned char> candidate(encoding.filter == PngRowFilter::SmallestSum ? stride + 1 : 0);
    for (int y = 0; y < height; ++y) {
        const auto row = rgb.subspan(static_cast<std::size_t>(y) * stride, stride);
        const auto above = y > 0 ? rgb.subspan(static_cast<std::size_t>(y - 1) * stride, stride)
                                 : std::span<const unsigned char>(zero_row);
        if (encoding.filter != PngRowFilter::SmallestSum) {
            filter_row(encoding.filter, row, above, chosen.data());
        } else {
            std::uint64_t best_sum = UINT64_MAX;
            for (const PngRowFilter filter : kFilters) {
                filter_row(filter, row, above, candidate.data());
                const std::uint64_t sum = sum_of_absolute_signed(candidate.data() + 1, stride);
                if (sum < best_sum) {
                    best_sum = sum;
                    chosen.swap(candidate);
                }
            }
        }
        deflater.add(chosen.data(), chosen.size(), y + 1 == height);
    }

    std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    const auto compressed = deflater.compressed();
    png.reserve(png.size() + 25 + compressed.size() + 12 * (compressed.size() / kMaxIdatBytes + 1) + 12);
    std::vector<unsigned char> header;
    append_be32(header, static_cast<std::uint32_t>(width));
    append_be32(header, static_cast<std::uint32_t>(height));
    header.insert(header.end(),
                  {8, 2, 0, 0, 0});  // depth 8, colour type 2 (RGB), deflate, adaptive filters, no interlace
    append_chunk(png, "IHDR", header.data(), header.size());
    for (std::size_t offset = 0; offset < compressed.size(); offset += kMaxIdatBytes) {
        append_chunk(png, "IDAT", compressed.data() + offset,
                     std::min(kMaxIdatBytes, compressed.size() - offset));
    }
    append_chunk(png, "IEND", nullptr, 0);
    return png;
}

std::vector<unsigned char> encode_png(const Image& image, const PngEncoding& encoding) {
    std::vector<unsigned char> pixels(image.rgb.size());
    std::transform(image.rgb.begin(), image.rgb.end(), pixels.begin(), linear_to_srgb8);
    return encode_png_rgb8(pixels, image.width, image.height, encoding);
}

}  // namespace glint
