#include "tile_parts.hpp"

#include <charconv>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <vector>

#include "glint/params/diagnostics.hpp"

namespace glint::cli {

namespace {

// A whole decimal number in [low, high] making up all of `text`.
template <typename Integer>
std::optional<Integer> parse_integer(const std::string& text, Integer low, Integer high) {
    Integer value{};
    const char* end = text.data() + text.size();
    const auto [at, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc{} || at != end || value < low || value > high) {
        return std::nullopt;
    }
    return value;
}

// `text` cut at each `separator`.
std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> pieces(1);
    for (const char c : text) {
        if (c == separator) {
            pieces.emplace_back();
        } else {
            pieces.back() += c;
        }
    }
    return pieces;
}

}  // namespace

std::optional<TileSpec> parse_tile(const std::string& text, std::string& error) {
    const std::vector<std::string> pieces = split(text, '/');
    constexpr int kMaxParts = 1 << 15;  // no more parts than rows of the largest film (kMaxFilmSide)
    const auto count = pieces.size() == 2 ? parse_integer<int>(pieces[1], 1, kMaxParts) : std::nullopt;
    const auto index = pieces.size() == 2 ? parse_integer<int>(pieces[0], 0, kMaxParts) : std::nullopt;
    if (!count || !index) {
        error = "not a part I/N (two whole numbers, I from 0 to N-1 and N from 1 to " +
                std::to_string(kMaxParts) + "; e.g. --tile 0/4)";
        return std::nullopt;
    }
    if (*index >= *count) {
        error = "part " + std::to_string(*index) + " of " + std::to_string(*count) +
                " does not exist: parts are numbered from 0 to " + std::to_string(*count - 1) +
                " (as Slurm's --array=0-" + std::to_string(*count - 1) + ")";
        return std::nullopt;
    }
    return TileSpec{*index, *count};
}

PixelWindow band_of(int index, int count, int width, int height) {
    const auto row = [&](int i) { return static_cast<int>(static_cast<std::int64_t>(i) * height / count); };
    return PixelWindow{0, row(index), width, row(index + 1)};
}

ExrAttributes part_attributes(const PartInfo& part) {
    char exposure[32];
    std::snprintf(exposure, sizeof(exposure), "%.17g", part.display.exposure);
    char hash[17];
    std::snprintf(hash, sizeof(hash), "%016llx", static_cast<unsigned long long>(part.scene_hash));
    const PixelWindow& w = part.window;
    return {
        {"glintVersion", part.version},
        {"glintPart", std::to_string(part.tile.index) + "/" + std::to_string(part.tile.count)},
        {"glintWindow", std::to_string(w.x0) + "," + std::to_string(w.y0) + "," + std::to_string(w.x1) + "," +
                            std::to_string(w.y1)},
        {"glintImageSize", std::to_string(part.width) + "x" + std::to_string(part.height)},
        {"glintSeed", std::to_string(part.seed)},
        {"glintSpp", std::to_string(part.samples_per_pixel)},
        {"glintSceneHash", hash},
        {"glintExposure", exposure},
        {"glintTonemap", tone_curve_table().name_of(part.display.curve)},
    };
}

PartInfo part_from_attributes(const ExrAttributes& attributes, const std::string& file) {
    if (attributes.find("glintPart") == attributes.end()) {
        throw std::runtime_error(file +
                                 ": not a part of a glint render (it has no glintPart attribute; parts are "
                                 "written by glint render --tile I/N -o part.exr)");
    }
    const auto text = [&](const char* name) -> const std::string& {
        const auto found = attributes.find(name);
        if (found == attributes.end()) {
            throw std::runtime_error(file + ": the glint part attribute " + name + " is missing");
        }
        return found->second;
    };
    const auto malformed = [&](const char* name, const std::string& expected) {
        return std::runtime_error(file + ": the glint part attribute " + name + " is '" +
                                  text(name).substr(0, 64) + "', not " + expected);
    };
    constexpr int kMaxSide = std::numeric_limits<int>::max();
    PartInfo part;
    part.version = text("glintVersion");

    std::string tile_error;
    const auto tile = parse_tile(text("glintPart"), tile_error);
    if (!tile) {
        throw malformed("glintPart", "a part I/N");
    }
    part.tile = *tile;

    const std::vector<std::string> size = split(text("glintImageSize"), 'x');
    const auto width = size.size() == 2 ? parse_integer<int>(size[0], 1, kMaxSide) : std::nullopt;
    const auto height = size.size() == 2 ? parse_integer<int>(size[1], 1, kMaxSide) : std::nullopt;
    if (!width || !height) {
        throw malformed("glintImageSize", "a size WIDTHxHEIGHT");
    }
    part.width = *width;
    part.height = *height;

    const std::vector<std::string> corners = split(text("glintWindow"), ',');
    std::optional<int> c[4];
    for (size_t i = 0; i < 4 && corners.size() == 4; ++i) {
        c[i] = parse_integer<int>(corners[i], 0, kMaxSide);
    }
    if (!c[0] || !c[1] || !c[2] || !c[3]) {
        throw malformed("glintWindow", "a window x0,y0,x1,y1");
    }
    part.window = PixelWindow{*c[0], *c[1], *c[2], *c[3]};

    const auto seed =
        parse_integer<std::uint64_t>(text("glintSeed"), 0, std::numeric_limits<std::uint64_t>::max());
    if (!seed) {
        throw malformed("glintSeed", "a seed");
    }
    part.seed = *seed;
    const auto spp = parse_integer<std::uint32_t>(text("glintSpp"), 0, kMaxSamplesPerPixel);
    if (!spp) {
        throw malformed("glintSpp", "a number of samples per pixel");
    }
    part.samples_per_pixel = *spp;

    const std::string& hash = text("glintSceneHash");
    std::uint64_t hash_value = 0;
    const auto [hash_end, hash_error] =
        std::from_chars(hash.data(), hash.data() + hash.size(), hash_value, 16);
    if (hash.size() != 16 || hash_error != std::errc{} || hash_end != hash.data() + hash.size()) {
        throw malformed("glintSceneHash", "16 hexadecimal digits");
    }
    part.scene_hash = hash_value;

    const std::string& exposure = text("glintExposure");
    double exposure_value = 0;
    const auto [exposure_end, exposure_error] =
        std::from_chars(exposure.data(), exposure.data() + exposure.size(), exposure_value);
    if (exposure_error != std::errc{} || exposure_end != exposure.data() + exposure.size()) {
        throw malformed("glintExposure", "a number of stops");
    }
    part.display.exposure = exposure_value;
    const std::string& curve = text("glintTonemap");
    const auto* entry = tone_curve_table().find(curve);
    if (!entry) {
        throw malformed("glintTonemap", "one of " + join_words(tone_curve_table().names()));
    }
    part.display.curve = entry->value;
    return part;
}

}  // namespace glint::cli
