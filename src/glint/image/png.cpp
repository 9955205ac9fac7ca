// PNG encoding through stb_image_write (Debian's libstb).
#include <stb_image_write.h>

#include <algorithm>

#include "glint/image/image_io.hpp"

namespace glint {

std::vector<unsigned char> encode_png(const Image& image) {
    std::vector<unsigned char> pixels(image.rgb.size());
    std::transform(image.rgb.begin(), image.rgb.end(), pixels.begin(), linear_to_srgb8);
    std::vector<unsigned char> bytes;
    const auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<unsigned char>*>(context);
        const auto* d = static_cast<const unsigned char*>(data);
        out->insert(out->end(), d, d + size);
    };
    if (!stbi_write_png_to_func(append, &bytes, image.width, image.height, 3, pixels.data(),
                                image.width * 3)) {
        throw ImageWriteError("PNG encoding failed");
    }
    return bytes;
}

}  // namespace glint
