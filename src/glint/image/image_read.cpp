// Reading images from files, for textures and environment maps: one loader for every format glint
// reads, so that each user of images accepts the same files. The file is read into memory once; its
// first bytes choose the decoder; its header is checked (image_headers.cpp) before the decoder
// allocates anything from it.
#include <fcntl.h>
#include <stb_image.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "glint/image/image_headers.hpp"
#include "glint/image/image_io.hpp"

namespace glint {

double srgb_to_linear(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

namespace image_detail {
namespace {

[[noreturn]] void fail(const std::string& name, const std::string& what) {
    throw std::runtime_error(name + ": " + what);
}

constexpr const char* kReadableFormats =
    "glint reads PNG, JPEG, BMP, TGA, binary PGM/PPM, Radiance HDR, OpenEXR and PFM";

class FileDescriptor {
  public:
    explicit FileDescriptor(int fd) : fd_(fd) {}
    ~FileDescriptor() { ::close(fd_); }
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    int get() const { return fd_; }

  private:
    int fd_;
};

struct StbFree {
    void operator()(void* pixels) const { stbi_image_free(pixels); }
};

// stb_image's pixels (bytes, 16-bit or floats, `channels` a pixel) to linear RGB: grey is copied to all
// three channels and alpha dropped. `to_unit` maps a sample to [0, 1]; `srgb` then decodes it.
template <typename Sample>
Image from_stb(Sample* pixels, int width, int height, int channels, double to_unit, bool srgb,
               const StbHeader& header, const std::string& name, const char* format) {
    if (!pixels) {
        const char* reason = stbi_failure_reason();
        fail(name, std::string("cannot decode the ") + format + " file (" +
                       (reason ? reason : "no reason given") + ")");
    }
    const std::unique_ptr<Sample, StbFree> owned(pixels);
    if (width != header.width || height != header.height) {  // cannot happen: stbi_info agreed
        fail(name, std::string(format) + " decoded to another size than its header declares");
    }
    Image image(width, height);
    const size_t count = static_cast<size_t>(width) * static_cast<size_t>(height);
    for (size_t i = 0; i < count; ++i) {
        for (size_t c = 0; c < 3; ++c) {
            const double v = static_cast<double>(pixels[i * channels + (channels >= 3 ? c : 0)]) * to_unit;
            image.rgb[3 * i + c] = static_cast<float>(srgb ? srgb_to_linear(v) : v);
        }
    }
    return image;
}

Image decode_with_stb(FileFormat format, const std::vector<unsigned char>& bytes, const std::string& name,
                      bool srgb) {
    const StbHeader header = check_stb_header(format, bytes.data(), bytes.size(), name);
    const char* format_text = format_name(format);
    const auto length = static_cast<int>(bytes.size());  // check_stb_header ensured it fits
    int width = 0, height = 0, file_channels = 0;
    if (format == FileFormat::Hdr) {
        float* pixels = stbi_loadf_from_memory(bytes.data(), length, &width, &height, &file_channels, 3);
        return from_stb(pixels, width, height, 3, 1.0, false, header, name, format_text);
    }
    // A PNM's maxval, not always 255 or 65535, is the sample value that means 1.
    const bool pnm = format == FileFormat::Pnm;
    if (header.sixteen_bit) {
        if (pnm) {
            // stb_image 2.27 mishandles 16-bit PNM (both fixed upstream in 2.28): asked for other channels
            // than the file's, it converts the samples as if they were bytes, returning a buffer half as
            // long as it reports; and it hands the big-endian samples over unswapped. So: the file's own
            // channels, samples swapped here.
            stbi_us* pixels = stbi_load_16_from_memory(bytes.data(), length, &width, &height, &file_channels,
                                                       header.channels);
            if (pixels) {
                const size_t count =
                    static_cast<size_t>(width) * static_cast<size_t>(height) * header.channels;
                const auto* raw = reinterpret_cast<const unsigned char*>(pixels);
                for (size_t i = 0; i < count; ++i) {
                    const auto big_endian = static_cast<stbi_us>((raw[2 * i] << 8) | raw[2 * i + 1]);
                    pixels[i] = big_endian;
                }
            }
            return from_stb(pixels, width, height, header.channels, 1.0 / header.max_value, srgb, header,
                            name, format_text);
        }
        stbi_us* pixels = stbi_load_16_from_memory(bytes.data(), length, &width, &height, &file_channels, 3);
        return from_stb(pixels, width, height, 3, 1.0 / 65535, srgb, header, name, format_text);
    }
    stbi_uc* pixels = stbi_load_from_memory(bytes.data(), length, &width, &height, &file_channels, 3);
    return from_stb(pixels, width, height, 3, 1.0 / (pnm ? header.max_value : 255), srgb, header, name,
                    format_text);
}

}  // namespace

std::vector<unsigned char> read_image_file(const std::filesystem::path& path) {
    const std::string name = path.string();
    // O_NONBLOCK: opening a FIFO must not wait for a writer; it is refused below as not a regular file.
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) {
        const int error = errno;
        fail(name, error == ENOENT ? std::string("no such file") : std::strerror(error));
    }
    const FileDescriptor file(fd);
    struct stat status {};
    if (::fstat(fd, &status) != 0) {
        fail(name, std::strerror(errno));
    }
    if (S_ISDIR(status.st_mode)) {
        fail(name, "is a folder, not an image file");
    }
    if (!S_ISREG(status.st_mode)) {
        fail(name, "is not a regular file");
    }
    const auto size = static_cast<std::uint64_t>(status.st_size);
    if (size == 0) {
        fail(name, "the file is empty");
    }
    if (size > kMaxImageFileBytes) {
        fail(name, "the file has " + std::to_string(size) + " bytes, more than the " +
                       std::to_string(kMaxImageFileBytes) + " glint reads as an image");
    }
    std::vector<unsigned char> bytes(size);
    size_t done = 0;
    while (done < size) {
        const ssize_t n = ::read(fd, bytes.data() + done, size - done);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n < 0) {
            fail(name, std::strerror(errno));
        }
        if (n == 0) {  // the file shrank while being read: the checks see what was read
            break;
        }
        done += static_cast<size_t>(n);
    }
    bytes.resize(done);
    return bytes;
}

}  // namespace image_detail

Image decode_image(const std::vector<unsigned char>& bytes, const std::string& name, bool srgb) {
    using image_detail::FileFormat;
    const FileFormat format = image_detail::sniff_format(bytes.data(), bytes.size());
    switch (format) {
        case FileFormat::Exr:
            return image_detail::decode_exr(bytes.data(), bytes.size(), name);
        case FileFormat::Pfm:
            return decode_pfm(bytes, name);
        case FileFormat::Jpeg:
            return image_detail::decode_jpeg(bytes.data(), bytes.size(), name, srgb);
        case FileFormat::Png:
        case FileFormat::Bmp:
        case FileFormat::Tga:
        case FileFormat::Pnm:
        case FileFormat::Hdr:
            return image_detail::decode_with_stb(format, bytes, name, srgb);
        case FileFormat::Gif:
        case FileFormat::Psd:
        case FileFormat::Pic:
            throw std::runtime_error(name + ": " + image_detail::format_name(format) +
                                     " files are not supported (" + image_detail::kReadableFormats + ")");
        case FileFormat::Unknown:
            break;
    }
    throw std::runtime_error(name + ": not an image file glint recognises (" +
                             image_detail::kReadableFormats + ")");
}

Image read_image(const std::filesystem::path& path, bool srgb) {
    return decode_image(image_detail::read_image_file(path), path.string(), srgb);
}

}  // namespace glint
