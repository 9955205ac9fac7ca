// OpenEXR through tinyexr (Debian's libtinyexr 1.0.1): encoding 32-bit float RGB, no loss; decoding R, G
// and B (or a single channel as grey) after checking the header, for tinyexr trusts it: a zero tile size
// divides by zero, an unknown tile level mode indexes an empty table, a large chunk count or data window
// is allocated before any pixel is read.
#include <tinyexr.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <stdexcept>
#include <string_view>

#include "glint/image/image_headers.hpp"
#include "glint/image/image_io.hpp"

namespace glint {

std::vector<unsigned char> encode_exr(const Image& image, const ExrAttributes& attributes,
                                      const std::vector<ImageLayer>& layers) {
    const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
    // Every channel as a plane of its own, named as OpenEXR's multi-layer convention has it: R, G, B for
    // the image, "layer.channel" for the rest (albedo.R, depth.Z); in name order, which OpenEXR requires.
    struct Plane {
        std::string name;
        std::vector<float> values;
    };
    std::vector<Plane> planes;
    for (int c = 0; c < 3; ++c) {
        Plane& plane = planes.emplace_back(Plane{std::string(1, "RGB"[c]), std::vector<float>(n)});
        for (size_t i = 0; i < n; ++i) {
            plane.values[i] = image.rgb[3 * i + static_cast<size_t>(c)];
        }
    }
    for (const ImageLayer& layer : layers) {
        if (layer.width != image.width || layer.height != image.height) {
            throw ImageWriteError("EXR layer '" + layer.name + "' is " + std::to_string(layer.width) + "x" +
                                  std::to_string(layer.height) + ", the image " +
                                  std::to_string(image.width) + "x" + std::to_string(image.height));
        }
        const size_t count = layer.channels.size();
        for (size_t c = 0; c < count; ++c) {
            Plane& plane =
                planes.emplace_back(Plane{layer.name + "." + layer.channels[c], std::vector<float>(n)});
            for (size_t i = 0; i < n; ++i) {
                plane.values[i] = layer.values[count * i + c];
            }
        }
    }
    std::sort(planes.begin(), planes.end(), [](const Plane& a, const Plane& b) { return a.name < b.name; });
    std::vector<float*> plane_ptrs;
    std::vector<EXRChannelInfo> channels(planes.size());
    std::vector<int> pixel_types(planes.size(), TINYEXR_PIXELTYPE_FLOAT);
    for (size_t c = 0; c < planes.size(); ++c) {
        if (planes[c].name.size() >= sizeof(channels[c].name)) {
            throw ImageWriteError("EXR channel name '" + planes[c].name + "' is too long");
        }
        std::snprintf(channels[c].name, sizeof(channels[c].name), "%s", planes[c].name.c_str());
        plane_ptrs.push_back(planes[c].values.data());
    }

    EXRHeader header;
    InitEXRHeader(&header);
    EXRImage exr;
    InitEXRImage(&exr);
    exr.num_channels = static_cast<int>(planes.size());
    exr.images = reinterpret_cast<unsigned char**>(plane_ptrs.data());
    exr.width = image.width;
    exr.height = image.height;
    header.num_channels = static_cast<int>(planes.size());
    header.channels = channels.data();
    header.pixel_types = pixel_types.data();
    header.requested_pixel_types = pixel_types.data();
    header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
    // Extra attributes as OpenEXR "string" attributes (the text, no terminating zero), in name order.
    std::vector<EXRAttribute> extra;
    for (const auto& [name, text] : attributes) {
        if (name.empty() || name.size() > 255 || text.empty() ||
            text.size() > static_cast<size_t>(INT32_MAX)) {
            throw ImageWriteError("EXR attribute '" + name.substr(0, 64) +
                                  "' has an empty or too long name or value");
        }
        EXRAttribute attribute{};
        std::snprintf(attribute.name, sizeof(attribute.name), "%s", name.c_str());
        std::snprintf(attribute.type, sizeof(attribute.type), "%s", "string");
        // tinyexr only reads the value while encoding; the cast is for its C interface.
        attribute.value = reinterpret_cast<unsigned char*>(const_cast<char*>(text.data()));
        attribute.size = static_cast<int>(text.size());
        extra.push_back(attribute);
    }
    header.num_custom_attributes = static_cast<int>(extra.size());
    header.custom_attributes = extra.empty() ? nullptr : extra.data();

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

namespace image_detail {
namespace {

[[noreturn]] void fail(const std::string& name, const std::string& what) {
    throw std::runtime_error(name + ": " + what);
}

// tinyexr's error message, freed; without its trailing newline.
std::string take_error(const char* error) {
    std::string message = error ? error : "no reason given";
    FreeEXRErrorMessage(error);
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) {
        message.pop_back();
    }
    return message;
}

struct HeaderOwner {
    EXRHeader header;
    HeaderOwner() { InitEXRHeader(&header); }
    ~HeaderOwner() { FreeEXRHeader(&header); }
    HeaderOwner(const HeaderOwner&) = delete;
    HeaderOwner& operator=(const HeaderOwner&) = delete;
};

// Owns a decoded image. Only a successful decode is handed over: when decoding fails tinyexr has already
// freed what it allocated, without clearing the pointers, so freeing again would free twice.
struct ImageOwner {
    EXRImage image;
    bool decoded = false;
    ImageOwner() { InitEXRImage(&image); }
    ~ImageOwner() {
        if (decoded) {
            FreeEXRImage(&image);
        }
    }
    ImageOwner(const ImageOwner&) = delete;
    ImageOwner& operator=(const ImageOwner&) = delete;
};

// The product, or the largest std::uint64_t if it is larger: hostile counts must not wrap round.
std::uint64_t saturating_product(std::initializer_list<std::uint64_t> factors) {
    std::uint64_t product = 1;
    for (const std::uint64_t factor : factors) {
        if (__builtin_mul_overflow(product, factor, &product)) {
            return UINT64_MAX;
        }
    }
    return product;
}

// Scanlines a chunk holds, as tinyexr decodes them.
std::int64_t lines_per_chunk(int compression) {
    switch (compression) {
        case TINYEXR_COMPRESSIONTYPE_ZIP:
            return 16;
        case TINYEXR_COMPRESSIONTYPE_PIZ:
            return 32;
        case TINYEXR_COMPRESSIONTYPE_ZFP:
            return 16;
        default:
            return 1;
    }
}

// The tiles of all levels of a tiled image, counted as tinyexr counts them (PrecalculateTileInfo).
std::uint64_t count_tiles(const EXRHeader& header, std::int64_t width, std::int64_t height) {
    const bool round_up = header.tile_rounding_mode == TINYEXR_TILE_ROUND_UP;
    const auto round_log2 = [&](std::int64_t x) {
        int log = 0;
        bool inexact = false;
        for (; x > 1; x >>= 1, ++log) {
            inexact = inexact || (x & 1) != 0;
        }
        return round_up && inexact ? log + 1 : log;
    };
    const auto tiles_along = [&](std::int64_t top, std::int64_t tile, int levels) {
        std::vector<std::uint64_t> tiles;
        for (int level = 0; level < levels; ++level) {
            const std::int64_t step = std::int64_t{1} << level;
            std::int64_t size = top / step;
            if (round_up && size * step < top) {
                ++size;
            }
            size = std::max<std::int64_t>(size, 1);
            tiles.push_back(static_cast<std::uint64_t>((size + tile - 1) / tile));
        }
        return tiles;
    };
    int x_levels = 1, y_levels = 1;
    if (header.tile_level_mode == TINYEXR_TILE_MIPMAP_LEVELS) {
        x_levels = y_levels = round_log2(std::max(width, height)) + 1;
    } else if (header.tile_level_mode == TINYEXR_TILE_RIPMAP_LEVELS) {
        x_levels = round_log2(width) + 1;
        y_levels = round_log2(height) + 1;
    }
    const auto x_tiles = tiles_along(width, header.tile_size_x, x_levels);
    const auto y_tiles = tiles_along(height, header.tile_size_y, y_levels);
    std::uint64_t total = 0;
    if (header.tile_level_mode == TINYEXR_TILE_RIPMAP_LEVELS) {
        for (const std::uint64_t across : x_tiles) {
            for (const std::uint64_t down : y_tiles) {
                total += across * down;
            }
        }
    } else {
        for (int level = 0; level < x_levels; ++level) {
            total += x_tiles[static_cast<size_t>(level)] * y_tiles[static_cast<size_t>(level)];
        }
    }
    return total;
}

// Picks the channels to read: R, G and B by name, or, failing that, the only R, G and B of a layer
// ("diffuse.R"), or a single channel of any name as grey.
void choose_channels(const EXRHeader& header, const std::string& name, int channel_of[3]) {
    const char* wanted[3] = {"R", "G", "B"};
    for (int pass = 0; pass < 2; ++pass) {
        int found[3] = {-1, -1, -1}, matches[3] = {0, 0, 0};
        for (int c = 0; c < header.num_channels; ++c) {
            const char* channel = header.channels[c].name;
            const char* dot = std::strrchr(channel, '.');
            const char* base = pass == 0 || !dot ? channel : dot + 1;
            for (int k = 0; k < 3; ++k) {
                if (std::strcmp(base, wanted[k]) == 0) {
                    found[k] = c;
                    ++matches[k];
                }
            }
        }
        if (matches[0] == 1 && matches[1] == 1 && matches[2] == 1) {
            std::copy(found, found + 3, channel_of);
            return;
        }
    }
    if (header.num_channels == 1) {
        channel_of[0] = channel_of[1] = channel_of[2] = 0;
        return;
    }
    std::string names;
    for (int c = 0; c < header.num_channels && c < 16; ++c) {
        names += (c > 0 ? ", " : "") + std::string(header.channels[c].name);
    }
    fail(name, "OpenEXR channels are " + names + "; glint reads R, G and B, or a single channel as grey");
}

// Walks the header's attributes before tinyexr parses them, refusing what tinyexr asserts on (Debian builds
// it with assertions, so a hostile header would abort the process): a "tiles" attribute whose value is
// not 9 bytes, a "type" that is not the image type the version field announces.
void check_exr_attributes(const unsigned char* data, std::size_t size, const EXRVersion& version,
                          const std::string& name) {
    std::size_t at = 8;  // after the magic number and the version field
    const auto text = [&](const char* what) {
        const auto* end = static_cast<const unsigned char*>(std::memchr(data + at, '\0', size - at));
        if (!end) {
            fail(name, std::string("OpenEXR header is truncated (in an attribute's ") + what + ")");
        }
        const std::string value(reinterpret_cast<const char*>(data + at),
                                static_cast<std::size_t>(end - (data + at)));
        at = static_cast<std::size_t>(end - data) + 1;
        return value;
    };
    for (;;) {
        if (at >= size) {
            fail(name, "OpenEXR header is truncated (no end of the attribute list)");
        }
        if (data[at] == '\0') {
            return;
        }
        const std::string attribute = text("name");
        text("type");
        if (size - at < 4) {
            fail(name, "OpenEXR header is truncated (in attribute " + attribute + ")");
        }
        const std::uint32_t length = data[at] | (std::uint32_t{data[at + 1]} << 8) |
                                     (std::uint32_t{data[at + 2]} << 16) |
                                     (std::uint32_t{data[at + 3]} << 24);
        at += 4;
        if (length > size - at) {
            fail(name, "OpenEXR attribute " + attribute + " is " + std::to_string(length) +
                           " bytes long, past the end of the file");
        }
        const std::string_view value(reinterpret_cast<const char*>(data + at), length);
        if (attribute == "tiles" && length != 9) {
            fail(name, "OpenEXR attribute tiles is " + std::to_string(length) + " bytes long, not 9");
        }
        if (attribute == "type") {
            const std::string type(value.substr(0, value.find('\0')));
            const char* expected = version.tiled ? "tiledimage" : "scanlineimage";
            if (!type.empty() && type != expected) {
                fail(name, "OpenEXR image type is '" + type.substr(0, 40) + "', not '" + expected +
                               "' as its version field says");
            }
        }
        at += length;
    }
}

Image decode_checked_exr(const unsigned char* data, std::size_t size, const std::string& name,
                         ExrAttributes* attributes) {
    EXRVersion version;
    if (ParseEXRVersionFromMemory(&version, data, size) != TINYEXR_SUCCESS) {
        fail(name, "not a readable OpenEXR file (bad version field)");
    }
    if (version.multipart || version.non_image) {
        fail(name, "multi-part and deep OpenEXR files are not supported");
    }
    check_exr_attributes(data, size, version, name);
    HeaderOwner owned_header;
    EXRHeader& header = owned_header.header;
    const char* error = nullptr;
    if (ParseEXRHeaderFromMemory(&header, &version, data, size, &error) != TINYEXR_SUCCESS) {
        fail(name, "OpenEXR header is invalid: " + take_error(error));
    }
    // Debian's tinyexr copies a PIZ chunk's bitmap (up to 8 KiB) without checking it against the
    // chunk's length, so a malformed PIZ file reads past the buffer (found by fuzz/image_exr). Until
    // EXR is read through a decoder that checks (OpenEXR), PIZ files are refused rather than trusted.
    if (header.compression_type == TINYEXR_COMPRESSIONTYPE_PIZ) {
        fail(name,
             "PIZ-compressed OpenEXR is not read (the decoder glint uses is not safe on malformed PIZ "
             "data); save the image with ZIP, RLE or no compression");
    }
    const EXRBox2i& window = header.data_window;
    const std::int64_t width = std::int64_t{window.max_x} - window.min_x + 1;
    const std::int64_t height = std::int64_t{window.max_y} - window.min_y + 1;
    check_declared_size(name, "OpenEXR", width, height);
    if (header.num_channels < 1) {
        fail(name, "OpenEXR file has no channels");
    }
    std::uint64_t pixel_bytes = 0;  // one pixel of all channels, as stored
    for (int c = 0; c < header.num_channels; ++c) {
        switch (header.pixel_types[c]) {
            case TINYEXR_PIXELTYPE_HALF:
                pixel_bytes += 2;
                break;
            case TINYEXR_PIXELTYPE_FLOAT:
            case TINYEXR_PIXELTYPE_UINT:
                pixel_bytes += 4;
                break;
            default:
                fail(name,
                     "OpenEXR channel " + std::string(header.channels[c].name) + " has an unknown type");
        }
    }
    const auto channels = static_cast<std::uint64_t>(header.num_channels);
    const auto pixels = static_cast<std::uint64_t>(width * height);
    // tinyexr decodes every channel of every pixel (of every tile, at full tile size) into 32-bit samples.
    std::uint64_t decoded_samples = channels * pixels;
    std::uint64_t chunks = 0;        // chunks of pixels in the file
    std::uint64_t chunk_header = 0;  // bytes before each chunk's data
    if (header.tiled) {
        if (header.tile_size_x < 1 || header.tile_size_y < 1 || header.tile_size_x > kMaxImageSide ||
            header.tile_size_y > kMaxImageSide) {
            fail(name, "OpenEXR tiles are " + std::to_string(header.tile_size_x) + " x " +
                           std::to_string(header.tile_size_y) + " pixels, not within 1 ... " +
                           std::to_string(kMaxImageSide) + " a side");
        }
        if (header.tile_level_mode < TINYEXR_TILE_ONE_LEVEL ||
            header.tile_level_mode > TINYEXR_TILE_RIPMAP_LEVELS ||
            header.tile_rounding_mode < TINYEXR_TILE_ROUND_DOWN ||
            header.tile_rounding_mode > TINYEXR_TILE_ROUND_UP) {
            fail(name, "OpenEXR tile description is invalid (level mode " +
                           std::to_string(header.tile_level_mode) + ", rounding mode " +
                           std::to_string(header.tile_rounding_mode) + ")");
        }
        chunks = count_tiles(header, width, height);
        chunk_header = 20;  // tile x, y, level x, level y, data size
        const std::uint64_t tile_pixels =
            static_cast<std::uint64_t>(header.tile_size_x) * static_cast<std::uint64_t>(header.tile_size_y);
        decoded_samples = std::max(decoded_samples, saturating_product({chunks, tile_pixels, channels}));
    } else {
        chunks = static_cast<std::uint64_t>((height + lines_per_chunk(header.compression_type) - 1) /
                                            lines_per_chunk(header.compression_type));
        chunk_header = 8;  // y, data size
    }
    if (decoded_samples > static_cast<std::uint64_t>(kMaxExrSamples)) {
        fail(name, "OpenEXR file decodes to " + std::to_string(decoded_samples) + " samples (" +
                       std::to_string(channels) + " channels of " + std::to_string(width) + " x " +
                       std::to_string(height) + " pixels" + (header.tiled ? ", in whole tiles" : "") +
                       "), more than the " + std::to_string(kMaxExrSamples) + " glint decodes");
    }
    // The offset table has one 8-byte entry a chunk (a chunkCount attribute, when present, sets its
    // length); each chunk has its header; uncompressed chunks hold every pixel's bytes.
    const std::uint64_t table_entries =
        header.chunk_count > 0 ? std::max(chunks, static_cast<std::uint64_t>(header.chunk_count)) : chunks;
    std::uint64_t needed = 8 + std::uint64_t{header.header_len} + 8 * table_entries + chunk_header * chunks;
    std::string why = std::to_string(table_entries) + " offset table entries and " + std::to_string(chunks) +
                      " chunk headers";
    if (header.compression_type == TINYEXR_COMPRESSIONTYPE_NONE) {
        needed += pixels * pixel_bytes;
        why += ", then " + std::to_string(pixel_bytes) + " uncompressed bytes a pixel";
    }
    check_file_holds(name, "OpenEXR", width, height, needed, size, why);

    for (int c = 0; c < header.num_channels; ++c) {
        if (header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF) {
            header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
        }
    }
    int channel_of[3];
    choose_channels(header, name, channel_of);
    if (attributes) {
        for (int a = 0; a < header.num_custom_attributes; ++a) {
            const EXRAttribute& attribute = header.custom_attributes[a];
            if (std::strcmp(attribute.type, "string") == 0 && attribute.size > 0 && attribute.value) {
                (*attributes)[attribute.name] = std::string(reinterpret_cast<const char*>(attribute.value),
                                                            static_cast<size_t>(attribute.size));
            }
        }
    }

    ImageOwner owned_image;
    EXRImage& exr = owned_image.image;
    // When a scanline image fails to decode, tinyexr frees it by its channel count, which it sets only
    // on success: without this the channels' planes would leak.
    exr.num_channels = header.num_channels;
    if (LoadEXRImageFromMemory(&exr, &header, data, size, &error) != TINYEXR_SUCCESS) {
        fail(name, "cannot decode the OpenEXR file: " + take_error(error));
    }
    owned_image.decoded = true;
    if (exr.width != width || exr.height != height || exr.num_channels != header.num_channels) {
        fail(name, "OpenEXR file decoded to another size than its header declares");
    }
    // A sample of channel c at index i of a decoded plane: 32-bit float, or 32-bit unsigned int.
    const auto sample = [&](unsigned char* const* planes, int c, size_t i) {
        if (header.requested_pixel_types[c] == TINYEXR_PIXELTYPE_UINT) {
            return static_cast<float>(reinterpret_cast<const std::uint32_t*>(planes[c])[i]);
        }
        return reinterpret_cast<const float*>(planes[c])[i];
    };
    Image image(static_cast<int>(width), static_cast<int>(height));
    if (!header.tiled) {
        if (!exr.images) {
            fail(name, "OpenEXR file decoded to no pixels");
        }
        for (size_t i = 0; i < pixels; ++i) {
            for (int k = 0; k < 3; ++k) {
                image.rgb[3 * i + static_cast<size_t>(k)] = sample(exr.images, channel_of[k], i);
            }
        }
        return image;
    }
    // Tiles of the first level, each decoded at the full tile size; those on the right and bottom edges
    // reach past the image.
    const std::int64_t tile_w = header.tile_size_x, tile_h = header.tile_size_y;
    for (int t = 0; t < exr.num_tiles; ++t) {
        const EXRTile& tile = exr.tiles[t];
        if (!tile.images) {
            fail(name, "OpenEXR file decoded to a tile without pixels");
        }
        for (std::int64_t j = 0; j < tile_h; ++j) {
            for (std::int64_t i = 0; i < tile_w; ++i) {
                const std::int64_t x = tile.offset_x * tile_w + i, y = tile.offset_y * tile_h + j;
                if (x < 0 || y < 0 || x >= width || y >= height) {
                    continue;
                }
                float* out = image.pixel(static_cast<int>(x), static_cast<int>(y));
                for (int k = 0; k < 3; ++k) {
                    out[k] = sample(tile.images, channel_of[k], static_cast<size_t>(i + j * tile_w));
                }
            }
        }
    }
    return image;
}

}  // namespace

Image decode_exr(const unsigned char* data, std::size_t size, const std::string& name,
                 ExrAttributes* attributes) {
    try {
        return decode_checked_exr(data, size, name, attributes);
    } catch (const std::runtime_error&) {
        throw;
    } catch (const std::exception& e) {  // tinyexr's std::vector::at, or memory running out
        fail(name, std::string("cannot decode the OpenEXR file: ") + e.what());
    }
}

}  // namespace image_detail

ExrFile read_exr(const std::filesystem::path& path) {
    const std::vector<unsigned char> bytes = image_detail::read_image_file(path);
    if (image_detail::sniff_format(bytes.data(), bytes.size()) != image_detail::FileFormat::Exr) {
        throw std::runtime_error(path.string() +
                                 ": not an OpenEXR file (a file of another format, or not an image)");
    }
    ExrFile file;
    file.image = image_detail::decode_exr(bytes.data(), bytes.size(), path.string(), &file.attributes);
    return file;
}

}  // namespace glint
