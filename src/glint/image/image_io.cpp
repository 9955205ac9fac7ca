#include "glint/image/image_io.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace glint {

std::optional<ImageFormat> image_format_for(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".png") {
        return ImageFormat::Png;
    }
    if (ext == ".pfm") {
        return ImageFormat::Pfm;
    }
    if (ext == ".exr") {
        return ImageFormat::Exr;
    }
    return std::nullopt;
}

std::string supported_image_extensions() {
    return ".png, .pfm, .exr";
}

unsigned char linear_to_srgb8(float linear) {
    const double c =
        std::clamp(static_cast<double>(linear), 0.0, 1.0);  // NaN is never written: the film counts it
    const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return static_cast<unsigned char>(std::lround(encoded * 255.0));
}

std::vector<unsigned char> encode_pfm(const Image& image) {
    std::ostringstream header;
    // A negative scale declares little-endian floats; rows go bottom to top.
    header << "PF\n" << image.width << ' ' << image.height << "\n-1.0\n";
    const std::string h = header.str();
    std::vector<unsigned char> bytes(h.begin(), h.end());
    static_assert(std::endian::native == std::endian::little, "PFM writer assumes a little-endian machine");
    const size_t row_bytes = static_cast<size_t>(image.width) * 3 * sizeof(float);
    for (int y = image.height - 1; y >= 0; --y) {
        const auto* row = reinterpret_cast<const unsigned char*>(image.pixel(0, y));
        bytes.insert(bytes.end(), row, row + row_bytes);
    }
    return bytes;
}

Image read_pfm(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    int width = 0;
    int height = 0;
    double scale = 0;
    if (!(in >> magic >> width >> height >> scale) || magic != "PF" || width <= 0 || height <= 0) {
        throw std::runtime_error(path.string() + ": not a colour PFM file");
    }
    in.get();  // the single whitespace after the scale
    Image image(width, height);
    const bool big_endian = scale > 0;
    for (int y = height - 1; y >= 0; --y) {
        in.read(reinterpret_cast<char*>(image.pixel(0, y)),
                static_cast<std::streamsize>(width) * 3 * sizeof(float));
    }
    if (!in) {
        throw std::runtime_error(path.string() + ": PFM file is truncated");
    }
    if (big_endian) {
        for (float& f : image.rgb) {
            f = std::bit_cast<float>(__builtin_bswap32(std::bit_cast<std::uint32_t>(f)));
        }
    }
    return image;
}

void write_file_atomically(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
    static std::atomic<unsigned> counter{0};
    std::filesystem::path temp = path;
    temp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    {
        std::FILE* f = std::fopen(temp.c_str(), "wb");
        if (!f) {
            throw ImageWriteError("cannot write '" + path.string() + "': " + std::strerror(errno));
        }
        const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size();
        const int saved_errno = errno;
        const bool closed = std::fclose(f) == 0;
        if (!ok || !closed) {
            std::filesystem::remove(temp);
            throw ImageWriteError("cannot write '" + path.string() +
                                  "': " + std::strerror(ok ? errno : saved_errno));
        }
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) {
        std::filesystem::remove(temp);
        throw ImageWriteError("cannot write '" + path.string() + "': " + ec.message());
    }
}

void write_image(const Image& image, const std::filesystem::path& path) {
    const std::optional<ImageFormat> format = image_format_for(path);
    if (!format) {
        throw ImageWriteError("cannot write '" + path.string() + "': unknown image format (use " +
                              supported_image_extensions() + ")");
    }
    switch (*format) {
        case ImageFormat::Png:
            write_file_atomically(path, encode_png(image));
            break;
        case ImageFormat::Pfm:
            write_file_atomically(path, encode_pfm(image));
            break;
        case ImageFormat::Exr:
            write_file_atomically(path, encode_exr(image));
            break;
    }
}

}  // namespace glint
