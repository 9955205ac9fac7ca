#include "samples_convergence.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <vector>

#include "glint/image/image_io.hpp"
#include "glint/sampling/convergence.hpp"
#include "glint/sampling/sampler.hpp"
#include "plot_canvas.hpp"

namespace glint_cli {
namespace {

// The slopes are fitted from this count on, where every curve has left its small-n regime.
constexpr std::uint32_t kFitFrom = 16;

const Colour kPalette[] = {{0.12f, 0.47f, 0.71f}, {1.0f, 0.50f, 0.05f},  {0.17f, 0.63f, 0.17f},
                           {0.84f, 0.15f, 0.16f}, {0.58f, 0.40f, 0.74f}, {0.55f, 0.34f, 0.29f},
                           {0.89f, 0.47f, 0.76f}, {0.10f, 0.75f, 0.81f}, {0.50f, 0.50f, 0.50f}};

std::string decade_label(int exponent) {
    if (exponent == 0)
        return "1";
    return "1e" + std::to_string(exponent);
}

// One log–log panel: the curves of one integrand.
void draw_panel(Canvas& canvas, double left, double top, double width, double height,
                const std::string& title, const std::vector<const glint::ConvergenceCurve*>& curves,
                std::uint32_t max_count) {
    const Colour black{0, 0, 0}, grid{0.88f, 0.88f, 0.88f}, guide{0.45f, 0.45f, 0.45f};
    double lo = 1e300, hi = 0;
    for (const auto* c : curves) {
        for (double r : c->rmse) {
            if (r > 0)
                lo = std::min(lo, r), hi = std::max(hi, r);
        }
    }
    if (!(hi > 0)) {
        lo = 0.1, hi = 1;  // no positive error to show: an empty decade
    }
    const int e_lo = static_cast<int>(std::floor(std::log10(lo)));
    const int e_hi = std::max(e_lo + 1, static_cast<int>(std::ceil(std::log10(hi))));
    const double lx_max = std::log(static_cast<double>(std::max(4u, max_count)));
    auto X = [&](double n) { return left + std::log(n) / lx_max * width; };
    auto Y = [&](double r) { return top + (e_hi - std::log10(r)) / (e_hi - e_lo) * height; };
    for (int e = e_lo; e <= e_hi; ++e) {
        canvas.line(left, Y(std::pow(10, e)), left + width, Y(std::pow(10, e)), 1, grid);
        const std::string label = decade_label(e);
        canvas.text(left - 8 - Canvas::text_width(label), Y(std::pow(10, e)) - 7, label, black);
    }
    for (std::uint32_t n = 1; n <= max_count; n *= 4) {
        canvas.line(X(n), top, X(n), top + height, 1, grid);
        const std::string label = std::to_string(n);
        canvas.text(X(n) - Canvas::text_width(label) / 2, top + height + 8, label, black);
    }
    canvas.line(left, top + height, left + width, top + height, 2, black);
    canvas.line(left, top, left, top + height, 2, black);
    canvas.text(left + width / 2 - Canvas::text_width("samples per pixel") / 2, top + height + 30,
                "samples per pixel", black);
    canvas.text(left, top - 24, title, black);
    // Guides: n^-1/2, n^-3/4 and n^-1 through the random curve's start.
    double start = hi;
    for (const auto* c : curves) {
        if (c->pattern == "random" && !c->rmse.empty())
            start = c->rmse.front();
    }
    for (const double slope : {-0.5, -0.75, -1.0}) {
        const double n_end = std::min<double>(max_count, std::pow(std::pow(10, e_lo) / start, 1 / slope));
        canvas.line(X(1), Y(start), X(n_end), Y(start * std::pow(n_end, slope)), 1, guide);
        char label[16];
        std::snprintf(label, sizeof(label), "n^%g", slope);
        canvas.text(X(n_end) + 4, Y(start * std::pow(n_end, slope)) - 12, label, guide, 1);
    }
    for (size_t i = 0; i < curves.size(); ++i) {
        const auto& c = *curves[i];
        const Colour colour = kPalette[i % std::size(kPalette)];
        for (size_t k = 0; k < c.samples.size(); ++k) {
            if (!(c.rmse[k] > 0))
                continue;
            canvas.disk(X(c.samples[k]), Y(c.rmse[k]), 3, colour);
            if (k + 1 < c.samples.size() && c.rmse[k + 1] > 0) {
                canvas.line(X(c.samples[k]), Y(c.rmse[k]), X(c.samples[k + 1]), Y(c.rmse[k + 1]), 2, colour);
            }
        }
    }
}

}  // namespace

void run_convergence(std::uint32_t pixels, std::uint32_t max_count, std::uint64_t seed,
                     const std::string& png_output) {
    std::vector<std::uint32_t> counts;
    for (std::uint32_t n = 1; n <= max_count; n *= 4)
        counts.push_back(n);
    const std::vector<std::string> patterns = glint::sampler_table().names();
    const std::vector<glint::TestIntegrand> integrands = {glint::edge_integrand(), glint::smooth_integrand()};
    const auto start = std::chrono::steady_clock::now();
    const std::vector<glint::ConvergenceCurve> curves =
        glint::convergence_study(patterns, integrands, counts, pixels, seed, kFitFrom);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    for (const glint::TestIntegrand& integrand : integrands) {
        std::printf(
            "\n### %s (exact integral %.12f)\n\nRMSE over %u pixels; slope fitted for n >= %u.\n\n| pattern "
            "|",
            integrand.name.c_str(), integrand.integral, pixels, kFitFrom);
        for (std::uint32_t n : counts)
            std::printf(" n=%u |", n);
        std::printf(" slope |\n|---|");
        for (size_t i = 0; i <= counts.size(); ++i)
            std::printf("---:|");
        std::printf("\n");
        for (const auto& c : curves) {
            if (c.integrand != integrand.name)
                continue;
            std::printf("| %s |", c.pattern.c_str());
            for (size_t k = 0; k < c.rmse.size(); ++k) {
                // Regular and jittered round the count up to a square: show what was taken.
                if (c.samples[k] != counts[k]) {
                    std::printf(" %.2e (%u) |", c.rmse[k], c.samples[k]);
                } else {
                    std::printf(" %.2e |", c.rmse[k]);
                }
            }
            std::printf(" %.2f |\n", c.slope);
        }
    }
    std::fprintf(stderr, "glint samples: convergence study took %.2f s\n", seconds);

    if (png_output.empty())
        return;
    const int panel_w = 440, panel_h = 360;
    Canvas canvas(1120, 560, {1, 1, 1});
    for (size_t k = 0; k < integrands.size(); ++k) {
        std::vector<const glint::ConvergenceCurve*> mine;
        for (const auto& c : curves) {
            if (c.integrand == integrands[k].name)
                mine.push_back(&c);
        }
        const std::string title =
            integrands[k].name == "edge" ? "rmse: pixel cut by an edge" : "rmse: smooth gaussian bump";
        draw_panel(canvas, 90 + k * 540.0, 50, panel_w, panel_h, title, mine, max_count);
    }
    for (size_t i = 0; i < patterns.size(); ++i) {
        const double x = 90 + (i % 4) * 250.0, y = 480 + (i / 4) * 30.0;
        const Colour colour = kPalette[i % std::size(kPalette)];
        canvas.line(x, y + 7, x + 30, y + 7, 3, colour);
        canvas.text(x + 40, y, patterns[i], {0, 0, 0});
    }
    try {
        glint::write_image(canvas.image(), png_output);
    } catch (const glint::ImageWriteError& e) {
        std::cerr << "glint samples: error: " << e.what() << '\n';
        throw CLI::RuntimeError(1);
    }
}

}  // namespace glint_cli
