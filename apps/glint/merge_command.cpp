// `glint merge PART... -o IMAGE`: the parts written by `glint render --tile I/N` put back together,
// bit for bit the image `glint render` writes in one go. Parts that do not belong together are refused
// before anything is written: another glint version, image size, part count, seed, sample count or scene
// (its hash), a part missing or given twice, a file that is not a part.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "glint/image/image_io.hpp"
#include "render_setup.hpp"
#include "tile_parts.hpp"

namespace {

using glint::cli::kExitBadInput;
using glint::cli::PartInfo;

struct MergeOptions {
    std::vector<std::string> parts;
    std::string output;
    bool quiet = false;
};

struct LoadedPart {
    std::string file;
    PartInfo info;
    glint::Image image;
};

std::string window_text(const glint::PixelWindow& w) {
    return std::to_string(w.x0) + "," + std::to_string(w.y0) + "," + std::to_string(w.x1) + "," +
           std::to_string(w.y1);
}

// The first way `part` differs from `first` (the first file given), or "" when it belongs with it.
std::string difference(const LoadedPart& part, const LoadedPart& first) {
    const PartInfo& a = part.info;
    const PartInfo& b = first.info;
    const auto differs = [&](const std::string& what, const std::string& mine, const std::string& theirs) {
        return part.file + ": its " + what + " is " + mine + ", but " + theirs + " in " + first.file;
    };
    char hash_a[17], hash_b[17];
    std::snprintf(hash_a, sizeof(hash_a), "%016llx", static_cast<unsigned long long>(a.scene_hash));
    std::snprintf(hash_b, sizeof(hash_b), "%016llx", static_cast<unsigned long long>(b.scene_hash));
    if (a.version != b.version) {
        return differs("glint version", a.version, b.version);
    }
    if (a.width != b.width || a.height != b.height) {
        return differs("image size", std::to_string(a.width) + "x" + std::to_string(a.height),
                       std::to_string(b.width) + "x" + std::to_string(b.height));
    }
    if (a.tile.count != b.tile.count) {
        return differs("number of parts", std::to_string(a.tile.count), std::to_string(b.tile.count));
    }
    if (a.seed != b.seed) {
        return differs("seed", std::to_string(a.seed), std::to_string(b.seed));
    }
    if (a.samples_per_pixel != b.samples_per_pixel) {
        return differs("samples per pixel", std::to_string(a.samples_per_pixel),
                       std::to_string(b.samples_per_pixel));
    }
    if (a.scene_hash != b.scene_hash) {
        return differs("scene (hash of the scene as built, after the flags and --set)", hash_a, hash_b);
    }
    if (a.display.exposure != b.display.exposure || a.display.curve != b.display.curve) {
        return differs("exposure or tone curve", "one", "another");
    }
    return "";
}

int run_merge(const MergeOptions& options) {
    const auto refuse = [](const std::string& message) {
        std::cerr << "glint: error: " << message << '\n';
        return kExitBadInput;
    };
    const std::filesystem::path output = options.output;
    try {
        glint::check_output_path(output);
    } catch (const glint::ImageWriteError& e) {
        return refuse(e.what());
    }

    std::vector<LoadedPart> parts;
    for (const std::string& file : options.parts) {
        try {
            glint::ExrFile exr = glint::read_exr(file);
            parts.push_back(
                {file, glint::cli::part_from_attributes(exr.attributes, file), std::move(exr.image)});
        } catch (const std::runtime_error& e) {
            return refuse(e.what());
        }
        const LoadedPart& part = parts.back();
        const PartInfo& info = part.info;
        if (const std::string why = difference(part, parts.front()); !why.empty()) {
            return refuse(why +
                          " (the parts of one image share glint's version, the image size, the number "
                          "of parts, the seed, the samples and the scene)");
        }
        // The window follows from the part's number; the pixels must fill it.
        const glint::PixelWindow expected =
            glint::cli::band_of(info.tile.index, info.tile.count, info.width, info.height);
        if (info.tile.count > info.height || info.window != expected ||
            part.image.width != expected.width() || part.image.height != expected.height()) {
            return refuse(file + ": part " + std::to_string(info.tile.index) + "/" +
                          std::to_string(info.tile.count) + " of a " + std::to_string(info.width) + "x" +
                          std::to_string(info.height) + " image should hold the pixels " +
                          window_text(expected) + ", but it records " + window_text(info.window) +
                          " and holds " + std::to_string(part.image.width) + "x" +
                          std::to_string(part.image.height) + " pixels");
        }
    }

    const PartInfo& first = parts.front().info;
    std::map<int, const LoadedPart*> by_index;
    for (const LoadedPart& part : parts) {
        const auto [at, inserted] = by_index.emplace(part.info.tile.index, &part);
        if (!inserted) {
            return refuse(part.file + ": part " + std::to_string(part.info.tile.index) + "/" +
                          std::to_string(first.tile.count) + " is given twice (also as " + at->second->file +
                          ")");
        }
    }
    if (static_cast<int>(by_index.size()) != first.tile.count) {
        std::string missing;
        int missing_count = 0;
        for (int i = 0; i < first.tile.count; ++i) {
            if (by_index.count(i) == 0 && ++missing_count <= 20) {
                missing += (missing.empty() ? "" : ", ") + std::to_string(i);
            }
        }
        if (missing_count > 20) {
            missing += ", …";
        }
        return refuse("the image of " + std::to_string(first.tile.count) + " parts is incomplete, " +
                      std::to_string(missing_count) + " missing: " + missing +
                      " (parts are numbered from 0; each is rendered by glint render --tile I/" +
                      std::to_string(first.tile.count) + ")");
    }

    glint::Image image(first.width, first.height);
    for (const auto& [index, part] : by_index) {
        const glint::Image& band = part->image;
        std::copy(band.rgb.begin(), band.rgb.end(), image.pixel(0, part->info.window.y0));
    }
    try {
        glint::write_image(image, output, first.display);
    } catch (const glint::ImageWriteError& e) {
        std::cerr << "glint: error: " << e.what() << '\n';
        return 1;
    }
    if (!options.quiet) {
        std::fprintf(stderr, "glint: merged %d parts into %s (%dx%d, %u spp)\n", first.tile.count,
                     output.string().c_str(), first.width, first.height, first.samples_per_pixel);
    }
    return 0;
}

}  // namespace

void add_merge_command(CLI::App& app) {
    auto options = std::make_shared<MergeOptions>();
    CLI::App* merge = app.add_subcommand(
        "merge",
        "Put the parts of glint render --tile I/N back together into one image (docs/distributed.md)");
    merge->add_option("parts", options->parts, "The part files (.exr), in any order")->required();
    merge->add_option("-o,--output", options->output, "The image to write: .exr, .pfm or .png")->required();
    merge->add_flag("-q,--quiet", options->quiet, "No summary");
    merge->callback([options] {
        if (const int code = run_merge(*options); code != 0) {
            throw CLI::RuntimeError(code);
        }
    });
}
