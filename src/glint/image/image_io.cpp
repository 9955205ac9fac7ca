#include "glint/image/image_io.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>

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
