// `glint samples`: look at a sample pattern (paper §II–III, figures 3–7) and measure it.
//
//   glint samples --pattern NAME --count N [--pixel X,Y] [--seed S] [--dimension D]
//                 [-o FILE.png|FILE.csv] [--warp disk|hemisphere[:e]|sphere] [--stats]
//   glint samples --convergence [--pixels P] [--max-count N] [-o plot.png]
//
// The points are those pixel (X, Y) gets from the pattern in dimension D during a render with seed S.
// A .png shows them in the unit square as the paper's figures do: the n × n and coarse grids, and the
// 1-D projections as ticks in the margins. A .csv (or stdout, without -o) lists them, one "x,y" line
// each after a header line. --stats prints the star discrepancy (L∞ exact and L2 by Warnock's formula),
// the minimum distance, and whether the n-rooks and jitter conditions hold.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "glint/core/vec.hpp"
#include "glint/image/image_io.hpp"
#include "glint/sampling/convergence.hpp"
#include "glint/sampling/multijittered.hpp"
#include "glint/sampling/pattern_stats.hpp"
#include "glint/sampling/sampler.hpp"
#include "glint/sampling/warps.hpp"
#include "glint/world/settings.hpp"
#include "plot_canvas.hpp"
#include "samples_convergence.hpp"

namespace {

using glint_cli::Canvas;
using glint_cli::Colour;

constexpr int kExitBadInput = 2;
constexpr int kExitFailure = 1;

[[noreturn]] void fail(int code, const std::string& message) {
    std::cerr << "glint samples: error: " << message << '\n';
    throw CLI::RuntimeError(code);
}

struct SamplesOptions {
    std::string pattern;
    std::uint32_t count = 16;
    std::string pixel = "0,0";
    std::uint64_t seed = glint::RenderSettings{}.seed;  // the render's default, so the points are its points
    std::uint32_t dimension = 0;
    std::string output;
    std::string warp;
    bool stats = false;
    bool convergence = false;
    std::uint32_t pixels = 1024;
    std::uint32_t max_count = 4096;
};

// ---------------------------------------------------------------------------------------------------
// --warp: the renderer's own warps (sampling/warps.hpp), so the plot shows what lenses and lights use.
enum class WarpKind { None, Disk, Hemisphere, Sphere };
struct Warp {
    WarpKind kind = WarpKind::None;
    double exponent = 1;  // hemisphere: density ∝ cos^e θ
};

Warp parse_warp(const std::string& text) {
    if (text.empty())
        return {};
    if (text == "disk")
        return {WarpKind::Disk, 1};
    if (text == "sphere")
        return {WarpKind::Sphere, 1};
    if (text.rfind("hemisphere", 0) == 0) {
        const std::string rest = text.substr(10);
        if (rest.empty())
            return {WarpKind::Hemisphere, 1};
        if (rest[0] == ':') {
            try {
                size_t used = 0;
                const double e = std::stod(rest.substr(1), &used);
                if (used == rest.size() - 1 && std::isfinite(e) && e >= 0)
                    return {WarpKind::Hemisphere, e};
            } catch (const std::exception&) {
            }
        }
    }
    fail(kExitBadInput,
         "--warp '" + text + "': expected disk, hemisphere, hemisphere:e (e ≥ 0, cos^e θ) or sphere");
}

glint::Vec3 apply_warp(const Warp& warp, glint::Point2 u) {
    switch (warp.kind) {
        case WarpKind::Disk: {
            const glint::Point2 p = glint::square_to_disk_concentric(u);
            return {p.x, p.y, 0};
        }
        case WarpKind::Hemisphere:
            return glint::square_to_cosine_power_hemisphere(u, warp.exponent);
        case WarpKind::Sphere:
            return glint::square_to_uniform_sphere(u);
        case WarpKind::None:
            break;
    }
    return {u.x, u.y, 0};
}
// ---------------------------------------------------------------------------------------------------

std::pair<std::uint32_t, std::uint32_t> parse_pixel(const std::string& text) {
    std::istringstream in(text);
    long long x = -1, y = -1;
    char comma = 0;
    if (in >> x >> comma >> y && comma == ',' && in.peek() == EOF && x >= 0 && y >= 0 && x < (1ll << 31) &&
        y < (1ll << 31)) {
        return {static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(y)};
    }
    fail(kExitBadInput, "--pixel '" + text + "': expected X,Y with non-negative integers, e.g. --pixel 3,7");
}

// Where -o writes: "" (stdout CSV), ".png" or ".csv". Checks the folder exists before any work.
std::string output_kind(const std::string& output, bool png_only) {
    if (output.empty())
        return "";
    const std::filesystem::path path(output);
    std::string ext = path.extension().string();
    for (char& c : ext)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".png" && (png_only || ext != ".csv")) {
        fail(kExitBadInput, "cannot write '" + output + "': use " + (png_only ? ".png" : ".png or .csv"));
    }
    const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
    if (!std::filesystem::is_directory(folder)) {
        fail(kExitBadInput,
             "cannot write '" + output + "': the folder '" + folder.string() + "' does not exist");
    }
    return ext;
}

void write_png(const Canvas& canvas, const std::string& output) {
    try {
        glint::write_image(canvas.image(), output);
    } catch (const glint::ImageWriteError& e) {
        fail(kExitFailure, e.what());
    }
}

// The most nearly square factorisation columns × rows of n (columns ≤ rows), as multi-jittered uses.
std::pair<std::uint32_t, std::uint32_t> coarse_grid(std::uint32_t n) {
    const glint::MultiJitteredSampler grid(n);
    return {grid.columns(), grid.rows()};
}

const Colour kWhite{1, 1, 1}, kBlack{0, 0, 0}, kFineGrid{0.86f, 0.86f, 0.86f},
    kCoarseGrid{0.55f, 0.55f, 0.55f}, kPointColour{0.05f, 0.15f, 0.55f}, kTickColour{0.75f, 0.1f, 0.1f},
    kBackSide{0.85f, 0.45f, 0.35f};

// The pattern in the unit square, like the paper's figures 3–7: fine n × n grid, coarse grid, points,
// and the x and y projections as ticks under and left of the square.
Canvas draw_pattern(const std::vector<glint::Point2>& points, const std::string& caption) {
    const int size = 512, margin = 44, top = 40;
    Canvas canvas(size + 2 * margin, size + margin + top + 4, kWhite);
    const double x0 = margin, y0 = top, s = size;
    auto px = [&](double x) { return x0 + x * s; };
    auto py = [&](double y) { return y0 + (1 - y) * s; };  // y up, as in the figures
    const auto n = static_cast<std::uint32_t>(points.size());
    if (n > 1 && s / n >= 3) {
        for (std::uint32_t i = 1; i < n; ++i) {
            canvas.fill_rect(px(double(i) / n) - 0.5, y0, px(double(i) / n) + 0.5, y0 + s, kFineGrid);
            canvas.fill_rect(x0, py(double(i) / n) - 0.5, x0 + s, py(double(i) / n) + 0.5, kFineGrid);
        }
    }
    const auto [columns, rows] = coarse_grid(n);
    if (columns > 1 || rows > 1) {
        for (std::uint32_t i = 1; i < columns; ++i) {
            canvas.fill_rect(px(double(i) / columns) - 1, y0, px(double(i) / columns) + 1, y0 + s,
                             kCoarseGrid);
        }
        for (std::uint32_t i = 1; i < rows; ++i) {
            canvas.fill_rect(x0, py(double(i) / rows) - 1, x0 + s, py(double(i) / rows) + 1, kCoarseGrid);
        }
    }
    // Frame.
    canvas.fill_rect(x0 - 2, y0 - 2, x0 + s + 2, y0, kBlack);
    canvas.fill_rect(x0 - 2, y0 + s, x0 + s + 2, y0 + s + 2, kBlack);
    canvas.fill_rect(x0 - 2, y0, x0, y0 + s, kBlack);
    canvas.fill_rect(x0 + s, y0, x0 + s + 2, y0 + s, kBlack);
    const double radius = std::clamp(s / std::sqrt(static_cast<double>(std::max(1u, n))) / 7, 1.3, 6.0);
    for (const glint::Point2& p : points) {
        canvas.disk(px(p.x), py(p.y), radius, kPointColour);
        canvas.line(px(p.x), y0 + s + 8, px(p.x), y0 + s + 26, 1.0, kTickColour);  // x projection
        canvas.line(x0 - 26, py(p.y), x0 - 8, py(p.y), 1.0, kTickColour);          // y projection
    }
    canvas.text(x0, 12, caption, kBlack, 2);
    return canvas;
}

// Warped points seen from above (+z): the unit disk, and for the sphere the far side in a lighter colour.
Canvas draw_warped(const std::vector<glint::Vec3>& points, const std::string& caption) {
    const int size = 512, margin = 44, top = 40;
    Canvas canvas(size + 2 * margin, size + margin + top + 4, kWhite);
    const double cx = margin + size / 2.0, cy = top + size / 2.0, r = size / 2.0;
    for (int i = 0; i < 256; ++i) {
        const double a = 2 * M_PI * i / 256, b = 2 * M_PI * (i + 1) / 256;
        canvas.line(cx + r * std::cos(a), cy - r * std::sin(a), cx + r * std::cos(b), cy - r * std::sin(b), 2,
                    kCoarseGrid);
    }
    canvas.line(cx - r, cy, cx + r, cy, 1, kFineGrid);
    canvas.line(cx, cy - r, cx, cy + r, 1, kFineGrid);
    const double radius =
        std::clamp(size / std::sqrt(static_cast<double>(std::max<size_t>(1, points.size()))) / 8, 1.2, 5.0);
    for (const glint::Vec3& p : points) {
        canvas.disk(cx + r * p.x, cy - r * p.y, radius, p.z < 0 ? kBackSide : kPointColour);
    }
    canvas.text(margin, 12, caption, kBlack, 2);
    return canvas;
}

void print_stats(const std::vector<glint::Point2>& points) {
    const auto n = static_cast<std::uint32_t>(points.size());
    std::printf("points                      %u\n", n);
    if (n <= 4096) {
        std::printf("star discrepancy (L-inf)    %.6f   (exact, over anchored boxes [0,a)x[0,b))\n",
                    glint::star_discrepancy_linf(points));
    } else {
        std::printf(
            "star discrepancy (L-inf)    skipped (n > 4096: the exact computation is O(n^2) memory)\n");
    }
    if (n <= 16384) {  // O(n²) time: a second at this size
        std::printf("star discrepancy (L2)       %.6f   (Warnock's formula)\n",
                    glint::star_discrepancy_l2(points));
    }
    std::printf("minimum distance            %.6f   (%.3f x 1/sqrt(n))\n", glint::minimum_distance(points),
                glint::minimum_distance(points) * std::sqrt(static_cast<double>(n)));
    std::printf("n-rooks (n x n grid)        %s\n", glint::satisfies_n_rooks(points) ? "yes" : "no");
    const auto k = static_cast<std::uint32_t>(std::lround(std::sqrt(static_cast<double>(n))));
    if (k * k == n) {
        std::printf("jittered (%u x %u cells)     %s\n", k, k,
                    glint::points_per_cell_equal(points, k, k) ? "yes" : "no");
    } else {
        const auto [columns, rows] = coarse_grid(n);
        std::printf("jittered (%u x %u cells)     %s   (n is not a square)\n", columns, rows,
                    glint::points_per_cell_equal(points, columns, rows) ? "yes" : "no");
    }
    if ((n & (n - 1)) == 0) {
        std::printf("(0,m,2)-net in base 2       %s\n", glint::is_base2_net(points) ? "yes" : "no");
    }
}

void run_samples(const SamplesOptions& options) {
    if (options.convergence) {
        output_kind(options.output, true);  // checks the path before the work
        glint_cli::run_convergence(options.pixels, options.max_count, options.seed, options.output);
        return;
    }
    if (options.pattern.empty()) {
        fail(kExitBadInput, "--pattern is required (or --convergence)");
    }
    const auto sampler = glint::make_sampler(options.pattern, options.count);
    if (!sampler) {
        std::string names;
        for (const std::string& name : glint::sampler_table().names())
            names += (names.empty() ? "" : ", ") + name;
        fail(kExitBadInput, "unknown pattern '" + options.pattern + "' (known: " + names + ")");
    }
    const auto [pixel_x, pixel_y] = parse_pixel(options.pixel);
    const Warp warp = parse_warp(options.warp);
    const std::string kind = output_kind(options.output, false);

    const std::vector<glint::Point2> points = glint::pattern_points(
        *sampler, glint::SampleKey{options.seed, pixel_x, pixel_y, 0}, options.dimension);
    std::vector<glint::Vec3> warped;
    for (const glint::Point2& p : points)
        warped.push_back(apply_warp(warp, p));

    if (options.stats) {
        print_stats(points);
    }
    if (kind == ".png") {
        std::string caption = options.pattern + "  n=" + std::to_string(points.size()) + "  pixel (" +
                              std::to_string(pixel_x) + "," + std::to_string(pixel_y) + ")";
        if (warp.kind != WarpKind::None) {
            write_png(draw_warped(warped, caption + "  " + options.warp), options.output);
        } else {
            write_png(draw_pattern(points, caption), options.output);
        }
        return;
    }
    if (kind.empty() && options.stats) {
        return;  // --stats alone: no point list
    }
    std::ostringstream csv;
    csv.precision(17);
    const bool three_d = warp.kind == WarpKind::Hemisphere || warp.kind == WarpKind::Sphere;
    csv << (three_d ? "x,y,z\n" : "x,y\n");
    for (const glint::Vec3& p : warped) {
        csv << p.x << ',' << p.y;
        if (three_d)
            csv << ',' << p.z;
        csv << '\n';
    }
    if (kind.empty()) {
        std::cout << csv.str();
    } else {
        const std::string text = csv.str();
        try {
            glint::write_file_atomically(options.output,
                                         std::vector<unsigned char>(text.begin(), text.end()));
        } catch (const std::exception& e) {
            fail(kExitFailure, e.what());
        }
    }
}

}  // namespace

void add_samples_command(CLI::App& app) {
    auto options = std::make_shared<SamplesOptions>();
    CLI::App* cmd =
        app.add_subcommand("samples", "Show or measure a sample pattern (points, plot, statistics)");
    std::string names;
    for (const std::string& name : glint::sampler_table().names())
        names += (names.empty() ? "" : ", ") + name;
    cmd->add_option("--pattern", options->pattern, "Sample pattern (" + names + ")");
    cmd->add_option("--count", options->count,
                    "Number of points requested (regular and jittered round up to a square)")
        ->check(CLI::Range(1u, 1u << 20));
    cmd->add_option("--pixel", options->pixel, "The pixel X,Y whose points to show (default 0,0)");
    cmd->add_option(
        "--seed", options->seed,
        "The render seed (default: the render's, " + std::to_string(glint::RenderSettings{}.seed) + ")");
    cmd->add_option("--dimension", options->dimension,
                    "The 2-D dimension: 0 film, 1 lens, 2… integrator (default 0)");
    cmd->add_option("-o,--output", options->output,
                    ".png: a plot; .csv: the points; none: the points on stdout");
    cmd->add_option("--warp", options->warp, "Map the points: disk, hemisphere[:e] (cos^e) or sphere");
    cmd->add_flag("--stats", options->stats,
                  "Print discrepancy, minimum distance, n-rooks and jitter conditions");
    cmd->add_flag(
        "--convergence", options->convergence,
        "RMSE against spp for every pattern on an edge and a smooth integrand: a table, and a plot with -o");
    cmd->add_option("--pixels", options->pixels,
                    "--convergence: pixels (randomisations) per estimate (default 1024)")
        ->check(CLI::Range(2u, 1u << 16));
    cmd->add_option("--max-count", options->max_count,
                    "--convergence: the largest sample count (default 4096)")
        ->check(CLI::Range(1u, 1u << 16));
    cmd->callback([options] { run_samples(*options); });
}
