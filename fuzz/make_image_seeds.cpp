// Writes the JPEG and EXR seeds of fuzz/corpus/ (the formats fuzz/make_seeds.py cannot write by hand),
// with the encoders of the Debian packages glint already uses: stb_image_write and tinyexr.
//   cmake --build --preset release --target fuzz_make_image_seeds
//   build/release/fuzz/fuzz_make_image_seeds fuzz/corpus
// Not part of any build by default: the seeds are committed; this says where they came from.
#include <stb_image_write.h>
#include <tinyexr.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

void write_file(const std::filesystem::path& path, const unsigned char* data, size_t size) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) {
        std::fprintf(stderr, "cannot write %s\n", path.c_str());
        std::exit(1);
    }
}

// A small picture with gradients and an edge, so that the encoders produce non-trivial blocks.
std::vector<unsigned char> picture(int width, int height, int channels) {
    std::vector<unsigned char> pixels;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            for (int c = 0; c < channels; ++c) {
                const double v = c == 0   ? x / (width - 1.0)
                                 : c == 1 ? y / (height - 1.0)
                                          : (x > y ? 0.9 : 0.1);
                pixels.push_back(static_cast<unsigned char>(std::lround(255 * v)));
            }
        }
    }
    return pixels;
}

void append(void* context, void* data, int size) {
    auto* bytes = static_cast<std::vector<unsigned char>*>(context);
    const auto* begin = static_cast<const unsigned char*>(data);
    bytes->insert(bytes->end(), begin, begin + size);
}

void write_jpeg(const std::filesystem::path& path, int width, int height, int channels, int quality) {
    std::vector<unsigned char> bytes;
    const std::vector<unsigned char> pixels = picture(width, height, channels);
    if (!stbi_write_jpg_to_func(append, &bytes, width, height, channels, pixels.data(), quality)) {
        std::fprintf(stderr, "JPEG encoding failed\n");
        std::exit(1);
    }
    write_file(path, bytes.data(), bytes.size());
}

// An EXR of `names` channels (planes of float values), stored as `pixel_type` with `compression`.
void write_exr(const std::filesystem::path& path, int width, int height,
               const std::vector<std::string>& names, int pixel_type, int compression, bool tiled = false) {
    const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
    std::vector<std::vector<float>> planes(names.size(), std::vector<float>(n));
    std::vector<float*> plane_pointers;
    for (size_t c = 0; c < names.size(); ++c) {
        for (size_t i = 0; i < n; ++i) {
            planes[c][i] =
                static_cast<float>((i % static_cast<size_t>(width)) * 0.25 + c * 0.5 + (i % 3 == 0 ? 8 : 0));
        }
        plane_pointers.push_back(planes[c].data());
    }
    EXRHeader header;
    InitEXRHeader(&header);
    EXRImage image;
    InitEXRImage(&image);
    image.num_channels = static_cast<int>(names.size());
    image.images = reinterpret_cast<unsigned char**>(plane_pointers.data());
    image.width = width;
    image.height = height;
    std::vector<EXRChannelInfo> channels(names.size());
    std::vector<int> stored(names.size(), pixel_type), given(names.size(), TINYEXR_PIXELTYPE_FLOAT);
    for (size_t c = 0; c < names.size(); ++c) {
        std::snprintf(channels[c].name, sizeof(channels[c].name), "%s", names[c].c_str());
    }
    header.num_channels = static_cast<int>(names.size());
    header.channels = channels.data();
    header.pixel_types = given.data();
    header.requested_pixel_types = stored.data();
    header.compression_type = compression;
    if (tiled) {
        header.tiled = 1;
        header.tile_size_x = 4;
        header.tile_size_y = 4;
        header.tile_level_mode = TINYEXR_TILE_ONE_LEVEL;
    }
    unsigned char* memory = nullptr;
    const char* error = nullptr;
    const size_t size = SaveEXRImageToMemory(&image, &header, &memory, &error);
    if (size == 0) {
        std::fprintf(stderr, "%s: EXR encoding failed: %s\n", path.c_str(), error ? error : "?");
        FreeEXRErrorMessage(error);
        std::exit(1);
    }
    write_file(path, memory, size);
    std::free(memory);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s fuzz/corpus\n", argv[0]);
        return 2;
    }
    const std::filesystem::path corpus = argv[1];
    write_jpeg(corpus / "image_jpeg" / "rgb-q90.jpg", 16, 16, 3, 90);
    write_jpeg(corpus / "image_jpeg" / "rgb-q20-odd-size.jpg", 13, 7, 3, 20);
    write_jpeg(corpus / "image_jpeg" / "gray.jpg", 8, 8, 1, 75);

    const std::vector<std::string> bgr = {"B", "G", "R"};
    write_exr(corpus / "image_exr" / "float-none.exr", 4, 3, bgr, TINYEXR_PIXELTYPE_FLOAT,
              TINYEXR_COMPRESSIONTYPE_NONE);
    write_exr(corpus / "image_exr" / "half-rle.exr", 5, 3, bgr, TINYEXR_PIXELTYPE_HALF,
              TINYEXR_COMPRESSIONTYPE_RLE);
    write_exr(corpus / "image_exr" / "half-zips.exr", 4, 4, bgr, TINYEXR_PIXELTYPE_HALF,
              TINYEXR_COMPRESSIONTYPE_ZIPS);
    write_exr(corpus / "image_exr" / "float-zip-rgba.exr", 6, 20, {"A", "B", "G", "R"},
              TINYEXR_PIXELTYPE_FLOAT, TINYEXR_COMPRESSIONTYPE_ZIP);
    write_exr(corpus / "image_exr" / "half-piz.exr", 8, 8, bgr, TINYEXR_PIXELTYPE_HALF,
              TINYEXR_COMPRESSIONTYPE_PIZ);
    write_exr(corpus / "image_exr" / "gray-y.exr", 3, 3, {"Y"}, TINYEXR_PIXELTYPE_FLOAT,
              TINYEXR_COMPRESSIONTYPE_NONE);
    write_exr(corpus / "image_exr" / "tiled-half.exr", 6, 5, bgr, TINYEXR_PIXELTYPE_HALF,
              TINYEXR_COMPRESSIONTYPE_ZIP,
              /*tiled=*/true);
    return 0;
}
