// PFM (Portable Float Map): "PF" (RGB) or "Pf" (grey), width, height and a scale whose sign gives the
// byte order (negative: little-endian), each followed by whitespace — a single byte after the scale —
// then 32-bit floats, rows from the bottom up, uncompressed.
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "glint/image/image_headers.hpp"
#include "glint/image/image_io.hpp"

namespace glint {

namespace {

[[noreturn]] void fail(const std::string& name, const std::string& what) {
    throw std::runtime_error(name + ": " + what);
}

bool pfm_space(unsigned char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

}  // namespace

namespace {

// A PFM of `channels` (3: "PF", 1: "Pf") interleaved floats per pixel, rows given top to bottom.
std::vector<unsigned char> encode_pfm_values(const float* values, int width, int height, int channels) {
    std::ostringstream header;
    // A negative scale declares little-endian floats; rows go bottom to top.
    header << (channels == 3 ? "PF" : "Pf") << '\n' << width << ' ' << height << "\n-1.0\n";
    const std::string h = header.str();
    std::vector<unsigned char> bytes(h.begin(), h.end());
    static_assert(std::endian::native == std::endian::little, "PFM writer assumes a little-endian machine");
    const size_t row_floats = static_cast<size_t>(width) * static_cast<size_t>(channels);
    for (int y = height - 1; y >= 0; --y) {
        const auto* row =
            reinterpret_cast<const unsigned char*>(values + static_cast<size_t>(y) * row_floats);
        bytes.insert(bytes.end(), row, row + row_floats * sizeof(float));
    }
    return bytes;
}

}  // namespace

std::vector<unsigned char> encode_pfm(const Image& image) {
    return encode_pfm_values(image.rgb.data(), image.width, image.height, 3);
}

std::vector<unsigned char> encode_pfm(const ImageLayer& layer) {
    if (layer.channels.size() != 1 && layer.channels.size() != 3) {
        throw ImageWriteError("PFM holds 1 or 3 channels; layer '" + layer.name + "' has " +
                              std::to_string(layer.channels.size()));
    }
    return encode_pfm_values(layer.values.data(), layer.width, layer.height,
                             static_cast<int>(layer.channels.size()));
}

Image decode_pfm(const std::vector<unsigned char>& bytes, const std::string& name) {
    const unsigned char* data = bytes.data();
    const size_t size = bytes.size();
    if (size < 3 || data[0] != 'P' || (data[1] != 'F' && data[1] != 'f') || !pfm_space(data[2])) {
        fail(name, "not a PFM file (it starts with neither \"PF\" nor \"Pf\")");
    }
    const int channels = data[1] == 'F' ? 3 : 1;
    size_t at = 2;
    // The next whitespace-separated field of the header.
    const auto field = [&](const char* what) {
        while (at < size && pfm_space(data[at])) {
            ++at;
        }
        const size_t start = at;
        while (at < size && !pfm_space(data[at]) && at - start < 64) {
            ++at;
        }
        if (at - start == 64) {
            fail(name, std::string("PFM ") + what + " is longer than any number glint reads");
        }
        if (at == start || at >= size) {
            fail(name, std::string("PFM header is truncated or has no ") + what +
                           " (expected PF or Pf, width, height, scale)");
        }
        return std::string_view(reinterpret_cast<const char*>(data + start), at - start);
    };
    const auto integer = [&](const char* what) {
        const std::string_view text = field(what);
        long long value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size()) {
            fail(name, std::string("PFM ") + what + " is '" + std::string(text) + "', not a whole number");
        }
        return value;
    };
    const long long width = integer("width");
    const long long height = integer("height");
    const std::string_view scale_text = field("scale");
    double scale = 0;
    const auto [end, error] =
        std::from_chars(scale_text.data(), scale_text.data() + scale_text.size(), scale);
    if (error != std::errc() || end != scale_text.data() + scale_text.size() || !std::isfinite(scale) ||
        scale == 0) {
        fail(name,
             "PFM scale is '" + std::string(scale_text) +
                 "'; it must be a nonzero number (negative: little-endian floats, positive: big-endian)");
    }
    ++at;  // the single whitespace byte before the floats
    image_detail::check_declared_size(name, "PFM", width, height);
    const std::uint64_t row_floats = static_cast<std::uint64_t>(width) * channels;
    const std::uint64_t needed = at + row_floats * static_cast<std::uint64_t>(height) * sizeof(float);
    image_detail::check_file_holds(name, "PFM", width, height, needed, size,
                                   std::to_string(at) + " of header and " + std::to_string(channels) +
                                       " uncompressed 32-bit floats a pixel");

    Image image(static_cast<int>(width), static_cast<int>(height));
    const bool big_endian = scale > 0;
    std::vector<float> row(row_floats);
    for (long long y = height - 1; y >= 0; --y, at += row_floats * sizeof(float)) {
        std::memcpy(row.data(), data + at, row_floats * sizeof(float));
        float* out = image.pixel(0, static_cast<int>(y));
        for (long long x = 0; x < width; ++x) {
            for (int c = 0; c < 3; ++c) {
                float v = row[static_cast<size_t>(x * channels + (channels == 3 ? c : 0))];
                if (big_endian) {
                    v = std::bit_cast<float>(__builtin_bswap32(std::bit_cast<std::uint32_t>(v)));
                }
                out[3 * x + c] = v;
            }
        }
    }
    return image;
}

Image read_pfm(const std::filesystem::path& path) {
    const std::vector<unsigned char> bytes = image_detail::read_image_file(path);
    return decode_pfm(bytes, path.string());
}

}  // namespace glint
