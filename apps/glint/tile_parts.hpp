// Parts of one image for a render farm: `glint render --tile I/N` renders part I of N, a band of rows,
// into an OpenEXR file whose header records what `glint merge` needs to put the parts back together and
// to refuse parts that do not belong together (docs/distributed.md).
//
// Parts are numbered from 0 to N-1, as Slurm's job arrays (--array=0-N-1), MPI ranks and most farm
// managers count. Part I holds rows [I·H/N, (I+1)·H/N): the bands differ by at most one row. Each part is
// rendered as a crop window (render.crop), so its pixels are exactly those of the whole render.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "glint/image/image_io.hpp"
#include "glint/image/tone_map.hpp"
#include "glint/world/settings.hpp"

namespace glint::cli {

struct TileSpec {
    int index = 0;  // 0 … count-1
    int count = 1;
};

// "I/N" with 0 ≤ I < N; nullopt and `error` set (what is wrong, to follow "--tile VALUE: ") otherwise.
std::optional<TileSpec> parse_tile(const std::string& text, std::string& error);

// Rows [index·height/count, (index+1)·height/count) across the whole width; count ≤ height.
PixelWindow band_of(int index, int count, int width, int height);

// What a part file records, besides its pixels.
struct PartInfo {
    std::string version;  // glint's
    TileSpec tile;
    PixelWindow window;         // the part's pixels in the whole image
    int width = 0, height = 0;  // of the whole image
    std::uint64_t seed = 0;
    std::uint32_t samples_per_pixel = 0;  // as taken
    std::uint64_t scene_hash = 0;         // render_setup.hpp, prepare_render
    DisplayTransform display;             // for a merge to PNG: the scene's exposure and tone curve
};

// The part as OpenEXR string attributes (names starting "glint"), and back. part_from_attributes throws
// std::runtime_error naming `file` and the attribute when one is missing or malformed; a file without
// the glintPart attribute is said not to be a part of a glint render.
ExrAttributes part_attributes(const PartInfo& part);
PartInfo part_from_attributes(const ExrAttributes& attributes, const std::string& file);

}  // namespace glint::cli
