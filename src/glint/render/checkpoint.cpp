#include "glint/render/checkpoint.hpp"

#include <bit>
#include <cmath>
#include <cstring>
#include <utility>

#include "glint/image/image_io.hpp"

namespace glint {

namespace {

// The file is the host's bytes: the format says little-endian, so a big-endian host must not write it.
static_assert(std::endian::native == std::endian::little, "checkpoints are written little-endian");

constexpr char kMagic[8] = {'G', 'L', 'I', 'N', 'T', 'C', 'K', 'P'};
constexpr std::uint32_t kFormatVersion = 1;
constexpr std::size_t kHeaderBytes = 8 + 4 + 8 + 4 * 4;
constexpr std::size_t kPixelBytes = 4 * 8 + 8;

// Writes into a buffer sized for the whole file up front.
class Writer {
  public:
    explicit Writer(std::size_t size) : bytes_(size) {}
    template <typename T>
    void put(const T& value) {
        std::memcpy(bytes_.data() + offset_, &value, sizeof(T));
        offset_ += sizeof(T);
    }
    std::vector<unsigned char> bytes() && { return std::move(bytes_); }

  private:
    std::vector<unsigned char> bytes_;
    std::size_t offset_ = 0;
};

// Reads what the header checks have already shown to be there.
class Reader {
  public:
    explicit Reader(const std::vector<unsigned char>& bytes) : bytes_(bytes) {}
    template <typename T>
    T next() {
        T value;
        std::memcpy(&value, bytes_.data() + offset_, sizeof(T));
        offset_ += sizeof(T);
        return value;
    }
    std::size_t offset() const { return offset_; }

  private:
    const std::vector<unsigned char>& bytes_;
    std::size_t offset_ = 0;
};

[[noreturn]] void fail(const std::string& name, const std::string& what) {
    throw CheckpointError(name + ": error: " + what);
}

}  // namespace

std::uint64_t checkpoint_file_bytes(int width, int height) {
    return kHeaderBytes +
           kPixelBytes * static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
}

std::vector<unsigned char> encode_checkpoint(const Checkpoint& checkpoint) {
    return encode_checkpoint(checkpoint.scene_fingerprint, checkpoint.samples_done, checkpoint.samples_asked,
                             checkpoint.film);
}

std::vector<unsigned char> encode_checkpoint(std::uint64_t scene_fingerprint, std::uint32_t samples_done,
                                             std::uint32_t samples_asked, const Film& film) {
    Writer out(checkpoint_file_bytes(film.width(), film.height()));
    out.put(kMagic);
    out.put(kFormatVersion);
    out.put(scene_fingerprint);
    out.put(static_cast<std::uint32_t>(film.width()));
    out.put(static_cast<std::uint32_t>(film.height()));
    out.put(samples_done);
    out.put(samples_asked);
    for (int y = 0; y < film.height(); ++y) {
        for (int x = 0; x < film.width(); ++x) {
            const Film::Pixel& pixel = film.raw_pixel(x, y);
            out.put(pixel.sum.r);
            out.put(pixel.sum.g);
            out.put(pixel.sum.b);
            out.put(pixel.luminance_squares);
            out.put(pixel.count);
        }
    }
    return std::move(out).bytes();
}

Checkpoint decode_checkpoint(const std::vector<unsigned char>& bytes, const std::string& name) {
    if (bytes.size() < kHeaderBytes || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0) {
        fail(name, "not a glint checkpoint (it does not start with GLINTCKP and a complete header)");
    }
    Reader in(bytes);
    in.next<std::uint64_t>();  // the magic, compared above
    const auto version = in.next<std::uint32_t>();
    if (version != kFormatVersion) {
        fail(name, "checkpoint format " + std::to_string(version) + "; this glint reads format " +
                       std::to_string(kFormatVersion));
    }
    Checkpoint checkpoint;
    checkpoint.scene_fingerprint = in.next<std::uint64_t>();
    const auto width = in.next<std::uint32_t>();
    const auto height = in.next<std::uint32_t>();
    checkpoint.samples_done = in.next<std::uint32_t>();
    checkpoint.samples_asked = in.next<std::uint32_t>();
    if (width == 0 || height == 0 || width > kMaxImageSide || height > kMaxImageSide ||
        std::uint64_t{width} * height > static_cast<std::uint64_t>(kMaxImagePixels)) {
        fail(name, "image size " + std::to_string(width) + " x " + std::to_string(height) +
                       " is outside 1 … " + std::to_string(kMaxImageSide) + " a side and " +
                       std::to_string(kMaxImagePixels) + " pixels");
    }
    if (checkpoint.samples_done == 0 || checkpoint.samples_done >= checkpoint.samples_asked) {
        fail(name, "it has " + std::to_string(checkpoint.samples_done) + " of " +
                       std::to_string(checkpoint.samples_asked) +
                       " samples per pixel; expected at least 1 and fewer than asked");
    }
    const std::uint64_t expected = checkpoint_file_bytes(static_cast<int>(width), static_cast<int>(height));
    if (bytes.size() != expected) {
        fail(name, "it is " + std::to_string(bytes.size()) + " bytes long; a " + std::to_string(width) +
                       " x " + std::to_string(height) + " checkpoint has " + std::to_string(expected));
    }
    checkpoint.film = Film(static_cast<int>(width), static_cast<int>(height));
    for (int y = 0; y < static_cast<int>(height); ++y) {
        for (int x = 0; x < static_cast<int>(width); ++x) {
            const std::size_t at = in.offset();
            Film::Pixel pixel;
            pixel.sum.r = in.next<double>();
            pixel.sum.g = in.next<double>();
            pixel.sum.b = in.next<double>();
            pixel.luminance_squares = in.next<double>();
            pixel.count = in.next<std::uint64_t>();
            if (!pixel.sum.is_finite() || !std::isfinite(pixel.luminance_squares) ||
                pixel.luminance_squares < 0 || pixel.count > checkpoint.samples_done) {
                fail(name, "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") at byte " +
                               std::to_string(at) + " holds a non-finite or negative sum or more than " +
                               std::to_string(checkpoint.samples_done) + " samples");
            }
            checkpoint.film.set_raw_pixel(x, y, pixel);
        }
    }
    return checkpoint;
}

void check_checkpoint_matches(const Checkpoint& checkpoint, const std::string& name,
                              std::uint64_t fingerprint, int width, int height, std::uint32_t samples_asked) {
    if (checkpoint.scene_fingerprint != fingerprint) {
        fail(name,
             "the checkpoint is of another render: the scene, its files' names, the flags or the --set "
             "edits differ from the ones it was made with (resume with the same command line)");
    }
    if (checkpoint.film.width() != width || checkpoint.film.height() != height) {
        fail(name, "the checkpoint is " + std::to_string(checkpoint.film.width()) + " x " +
                       std::to_string(checkpoint.film.height()) + " pixels; this render is " +
                       std::to_string(width) + " x " + std::to_string(height));
    }
    if (checkpoint.samples_asked != samples_asked) {
        fail(name, "the checkpoint's render asks " + std::to_string(checkpoint.samples_asked) +
                       " samples per pixel; this one " + std::to_string(samples_asked));
    }
}

}  // namespace glint
