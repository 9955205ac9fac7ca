// OpenEXR encoding through tinyexr (Debian's libtinyexr): 32-bit float RGB, no loss.
#include <tinyexr.h>

#include <cstdlib>

#include "glint/image/image_io.hpp"

namespace glint {

std::vector<unsigned char> encode_exr(const Image& image) {
    const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
    // EXR stores channels as separate planes, conventionally in B, G, R order.
    std::vector<float> planes[3];
    for (auto& p : planes) {
        p.resize(n);
    }
    for (size_t i = 0; i < n; ++i) {
        planes[0][i] = image.rgb[3 * i + 2];
        planes[1][i] = image.rgb[3 * i + 1];
        planes[2][i] = image.rgb[3 * i + 0];
    }
    float* plane_ptrs[3] = {planes[0].data(), planes[1].data(), planes[2].data()};

    EXRHeader header;
    InitEXRHeader(&header);
    EXRImage exr;
    InitEXRImage(&exr);
    exr.num_channels = 3;
    exr.images = reinterpret_cast<unsigned char**>(plane_ptrs);
    exr.width = image.width;
    exr.height = image.height;

    EXRChannelInfo channels[3] = {};
    const char* names[3] = {"B", "G", "R"};
    int pixel_types[3] = {TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT, TINYEXR_PIXELTYPE_FLOAT};
    for (int c = 0; c < 3; ++c) {
        std::snprintf(channels[c].name, sizeof(channels[c].name), "%s", names[c]);
    }
    header.num_channels = 3;
    header.channels = channels;
    header.pixel_types = pixel_types;
    header.requested_pixel_types = pixel_types;
    header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;

    unsigned char* memory = nullptr;
    const char* error = nullptr;
    const size_t size = SaveEXRImageToMemory(&exr, &header, &memory, &error);
    if (size == 0) {
        std::string message = error ? error : "unknown error";
        FreeEXRErrorMessage(error);
        throw ImageWriteError("EXR encoding failed: " + message);
    }
    std::vector<unsigned char> bytes(memory, memory + size);
    std::free(memory);
    return bytes;
}

}  // namespace glint
