#include "render_setup.hpp"

#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "glint/scene/scene_checks.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_writer.hpp"

namespace glint::cli {

std::filesystem::path render_output_path(const RenderOptions& options) {
    if (!options.output.empty()) {
        return options.output;
    }
    return options.scene_path.empty() ? "default.png"
                                      : std::filesystem::path(options.scene_path).stem().string() + ".png";
}

namespace {

// 64-bit FNV-1a: stable across machines and builds, which std::hash is not.
std::uint64_t fnv1a(const std::string& text) {
    std::uint64_t hash = 0xcbf29ce484222325ull;
    for (const unsigned char c : text) {
        hash = (hash ^ c) * 0x100000001b3ull;
    }
    return hash;
}

}  // namespace

bool needs_scene_hash(const RenderOptions& options) {
    return !options.resume.empty() || !options.checkpoint.empty() || options.tile.has_value();
}

PreparedRender prepare_render(const RenderOptions& options, bool print_warnings, bool with_scene_hash) {
    SceneDesc desc =
        options.scene_path.empty() ? default_scene() : load_scene(options.scene_path, options.import);
    if (print_warnings) {
        ::print_warnings(desc);
    }
    // The flags are short forms of --set: each is an edit of the scene's tree, checked by the builder like
    // the file; the --set edits follow them, in order.
    apply_flags_and_sets(desc, options.flags, options.sets);
    PreparedRender prepared;
    if (with_scene_hash) {
        prepared.scene_hash =
            fnv1a(std::string("glint ") + GLINT_VERSION + "\n" + write_scene_yaml(desc.root));
    }
    const Node* camera = desc.root.find("camera");
    prepared.camera_yaml = camera ? write_scene_yaml(*camera) : "{} (the default camera)";
    prepared.scene = build_scene(desc);
    if (print_warnings) {
        for (const std::string& warning : scene_warnings(prepared.scene)) {
            std::cerr << "glint: warning: " << warning << '\n';
        }
    }
    if (options.threads) {
        prepared.scene.view.settings.threads = *options.threads;
    }
    return prepared;
}

Image film_window(const Film& film, const PixelWindow& window) {
    return film.to_image(window.x0, window.y0, window.width(), window.height());
}

void print_nonfinite_warning(const RenderStats& stats) {
    if (stats.nonfinite_samples > 0) {
        std::fprintf(stderr,
                     "glint: warning: %llu samples were NaN or infinite and were left out of the image "
                     "(first at pixel (%d, %d), sample %u)\n",
                     static_cast<unsigned long long>(stats.nonfinite_samples), stats.first_nonfinite_x,
                     stats.first_nonfinite_y, stats.first_nonfinite_sample);
    }
}

std::string rays_summary(const RayCounters& rays) {
    char text[160];
    std::snprintf(text, sizeof text, "%.2f M rays (%.2f M camera, %.2f M bounces, %.2f M shadow)",
                  static_cast<double>(rays.total()) * 1e-6, static_cast<double>(rays.camera) * 1e-6,
                  static_cast<double>(rays.secondary) * 1e-6, static_cast<double>(rays.shadow) * 1e-6);
    return text;
}

ProgressBar::ProgressBar(bool enabled) : enabled_(enabled), start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(double fraction) {
    if (!enabled_) {
        return;
    }
    const auto now = std::chrono::steady_clock::now();
    if (fraction < 1.0 && now - last_draw_ < std::chrono::milliseconds(100)) {
        return;
    }
    last_draw_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth);
    std::string bar(static_cast<size_t>(filled), '#');
    bar.resize(kWidth, '.');
    char eta[32] = "--";
    if (fraction > 0.01) {
        std::snprintf(eta, sizeof(eta), "%.1fs", elapsed * (1 - fraction) / fraction);
    }
    std::fprintf(stderr, "\r[%s] %5.1f%%  elapsed %.1fs  ETA %s   ", bar.c_str(), 100 * fraction, elapsed,
                 eta);
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (enabled_) {
        std::fprintf(stderr, "\r%*s\r", 70, "");
    }
}

}  // namespace glint::cli
