// Harnesses image_png, image_bmp, image_pnm, image_tga, image_hdr, image_jpeg, image_pfm, image_exr:
// a file through glint::read_image, the reader of textures and environment maps. read_image picks
// tinyexr or read_pfm by the extension and lets stb_image recognise the rest by content, so each
// family gets its own harness, extension, seeds and dictionary: the fuzzer then spends its time
// inside one decoder.
//
// Findings: a crash, a leak, a hang, unbounded memory (a size read from the file must be checked
// before it is allocated), an exception other than std::runtime_error, or an image whose pixel array
// does not match its size.
#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "fuzz_support.hpp"
#include "glint/image/image_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const glint::fuzz::TemporaryInputFile input(GLINT_FUZZ_EXTENSION, data, size);
    const std::filesystem::path& path = input.path();
    try {
        const glint::Image image = glint::read_image(path);
        // An empty image may come back (stb accepts a BMP of height 0): the texture builder refuses it.
        GLINT_FUZZ_CHECK(image.width >= 0 && image.height >= 0);
        GLINT_FUZZ_CHECK(image.rgb.size() ==
                         static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3);
    } catch (const std::runtime_error& e) {
        // Unreadable: the documented outcome. (The texture and environment builders add the path.)
        glint::fuzz::refused(e);
    }
    return 0;
}
