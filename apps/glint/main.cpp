// glint: the command-line tool. Thin by design: it parses flags and calls the library.
//
// Exit codes: 0 success; 2 bad input (scene file, flags, output path); 130 interrupted (Ctrl-C; the
// image reached so far is written on the first one); 143 terminated (SIGTERM); 1 anything else (a
// failed write, out of memory, an internal error). Nothing escapes main(): every exception becomes a
// message and one of these codes.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <new>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "glint/image/image_io.hpp"
#include "glint/import/importer.hpp"
#include "glint/params/diagnostics.hpp"
#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_checks.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitInterrupted = 128 + SIGINT;

// Ctrl-C during a render: the first asks the render to stop after its current pass (and the image so
// far to be written); a second, or SIGTERM, ends the process at once. Only async-signal-safe calls in
// the handler: lock-free atomics, write(2), unlink(2) (in remove_pending_temporary_files) and _exit(2);
// errno is kept for the code the signal interrupted.
std::atomic<bool> g_stop_after_pass{false};
std::atomic<int> g_interrupts{0};

extern "C" void on_stop_signal(int signal) {
    const int saved_errno = errno;
    // exchange, not a read then a write: two SIGINTs may arrive on two threads at once.
    if (signal == SIGINT && g_interrupts.exchange(1) == 0) {
        g_stop_after_pass.store(true);
        static const char message[] =
            "\nglint: stopping after this pass to write the image so far "
            "(Ctrl-C again to quit without writing)\n";
        [[maybe_unused]] const auto written = ::write(STDERR_FILENO, message, sizeof(message) - 1);
        errno = saved_errno;
        return;
    }
    glint::remove_pending_temporary_files();  // a half-written image must not stay behind
    ::_exit(128 + signal);
}

void install_stop_handlers() {
    static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
                  "the signal handler needs lock-free atomics");
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);
}

// A progress bar on stderr: percentage, elapsed time and an estimate of the time left.
class ProgressBar {
  public:
    explicit ProgressBar(bool enabled) : enabled_(enabled), start_(std::chrono::steady_clock::now()) {}

    void update(double fraction) {
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
    void finish() {
        if (enabled_) {
            std::fprintf(stderr, "\r%*s\r", 70, "");
        }
    }

  private:
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point last_draw_{};
};

struct RenderOptions {
    std::string scene_path;
    std::string output;
    glint::RenderFlags flags;
    std::optional<int> threads;     // not a scene key: it does not change the image
    std::vector<std::string> sets;  // --set key.path=value, in order
    bool quiet = false;
    glint::ImportOptions import;  // for scenes of other tools (glint/import)
    double time_limit = 0;        // seconds; 0: none
};

int bad_input(const std::string& message) {
    std::cerr << "glint: error: " << message << '\n';
    return kExitBadInput;
}

int run_render(const RenderOptions& options) {
    // Check the output path before spending time on the render.
    std::filesystem::path output = options.output;
    if (output.empty()) {
        output = options.scene_path.empty()
                     ? "default.png"
                     : std::filesystem::path(options.scene_path).stem().string() + ".png";
    }
    try {
        glint::check_output_path(output);
    } catch (const glint::ImageWriteError& e) {
        return bad_input(e.what());
    }

    install_stop_handlers();
    glint::Scene scene;
    try {
        glint::SceneDesc desc = options.scene_path.empty()
                                    ? glint::default_scene()
                                    : glint::load_scene(options.scene_path, options.import);
        print_warnings(desc);
        // The flags are short forms of --set: each is an edit of the scene's tree, checked by the
        // builder like the file; the --set edits follow them, in order.
        glint::apply_flags(desc, options.flags);
        for (const std::string& set : options.sets) {
            glint::apply_set(desc, set);
        }
        scene = glint::build_scene(desc);
        for (const std::string& warning : glint::scene_warnings(scene)) {
            std::cerr << "glint: warning: " << warning << '\n';
        }
        if (options.threads) {
            scene.view.settings.threads = *options.threads;
        }
    } catch (const glint::SceneError& e) {
        std::cerr << e.what() << '\n';
        return kExitBadInput;
    }
    if (g_stop_after_pass.load()) {
        std::cerr << "glint: interrupted before rendering; no image written\n";
        return kExitInterrupted;
    }

    glint::Film film(scene.view.settings.width, scene.view.settings.height);
    ProgressBar bar(!options.quiet && ::isatty(STDERR_FILENO));
    glint::RenderCallbacks callbacks;
    callbacks.progress = [&bar](double fraction) { bar.update(fraction); };
    callbacks.stop_after_pass = &g_stop_after_pass;
    callbacks.time_limit_seconds = options.time_limit;
    const glint::RenderStats stats = glint::render(scene, film, callbacks);
    bar.finish();

    if (stats.nonfinite_samples > 0) {
        std::fprintf(stderr,
                     "glint: warning: %llu samples were NaN or infinite and were left out of the image "
                     "(first at pixel (%d, %d), sample %u)\n",
                     static_cast<unsigned long long>(stats.nonfinite_samples), stats.first_nonfinite_x,
                     stats.first_nonfinite_y, stats.first_nonfinite_sample);
    }
    glint::Image image = film.to_image();
    if (const auto& crop = scene.view.settings.crop) {  // only the window was rendered: write it alone
        glint::Image window(crop->width(), crop->height());
        for (int y = 0; y < crop->height(); ++y) {
            const float* from = image.pixel(crop->x0, crop->y0 + y);
            std::copy(from, from + 3 * crop->width(), window.pixel(0, y));
        }
        image = std::move(window);
    }
    if (glint::all_black(image) && !stats.cancelled) {
        std::fprintf(stderr,
                     "glint: warning: every pixel of the image is black (no light reaches the camera: "
                     "check the lights, the camera's direction and the integrator)\n");
    }
    try {
        glint::write_image(image, output, scene.view.settings.display);
    } catch (const glint::ImageWriteError& e) {
        std::cerr << "glint: error: " << e.what() << '\n';
        return 1;
    }
    if (stats.cancelled) {
        // Each pixel is the mean of the samples it has: an unfinished render, not a darker one.
        std::fprintf(stderr, "glint: interrupted: wrote %s with %u of %u samples per pixel\n",
                     output.string().c_str(), stats.samples_per_pixel, scene.view.settings.samples_per_pixel);
        return kExitInterrupted;
    }
    if (stats.time_limit_reached) {
        // Not an error: the image is what the time allowed, every pixel with the same samples.
        std::fprintf(stderr, "glint: time limit of %g s reached: %s has %u of %u samples per pixel\n",
                     options.time_limit, output.string().c_str(), stats.samples_per_pixel,
                     scene.view.settings.samples_per_pixel);
    }
    if (!options.quiet) {
        std::fprintf(stderr, "glint: %dx%d, %u spp, %.2f s, %.2f M rays, %.2f Mrays/s -> %s\n",
                     scene.view.settings.width, scene.view.settings.height, stats.samples_per_pixel,
                     stats.seconds, stats.rays.total() * 1e-6, stats.mrays_per_second(),
                     output.string().c_str());
    }
    return 0;
}

// The command line's mistakes, said as well as the scene file's: an unknown command or option with a
// did-you-mean, a value that is not a number named as such. Exit code 2.
int command_line_error(CLI::App& app, int argc, char** argv, const CLI::ParseError& error) {
    std::vector<std::string> commands;
    for (const CLI::App* command : app.get_subcommands({})) {
        commands.push_back(command->get_name());
    }
    const std::string first = argc > 1 ? argv[1] : "";
    if (!first.empty() && first[0] != '-' &&
        std::find(commands.begin(), commands.end(), first) == commands.end()) {
        std::cerr << "glint: error: " << glint::unknown_name_message("command", first, commands, "commands")
                  << '\n';
        return kExitBadInput;
    }
    // The subcommand given, whose options an unknown one is compared with.
    const CLI::App* command = &app;
    for (const CLI::App* sub : app.get_subcommands({})) {
        if (sub->get_name() == first) {
            command = sub;
        }
    }
    std::vector<std::string> options;
    for (const CLI::Option* option : command->get_options()) {
        for (const std::string& name : option->get_lnames()) {
            options.push_back("--" + name);
        }
    }
    const std::string what = error.what();
    if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
        for (int i = 2; i < argc; ++i) {
            const std::string word = argv[i];
            if (word.rfind("--", 0) == 0 &&
                std::find(options.begin(), options.end(), word.substr(0, word.find('='))) == options.end()) {
                std::cerr << "glint: error: "
                          << glint::unknown_name_message("option", word.substr(0, word.find('=')), options,
                                                         "options")
                          << '\n';
                return kExitBadInput;
            }
        }
    }
    if (dynamic_cast<const CLI::ConversionError*>(&error) ||
        what.find("Could not convert") != std::string::npos) {
        // CLI11 says "Could not convert: --spp = abc".
        std::cerr << "glint: error: "
                  << what.substr(what.find(':') == std::string::npos ? 0 : what.find(':') + 2)
                  << ": not a number (or not one this option takes)\n";
        return kExitBadInput;
    }
    if (dynamic_cast<const CLI::RequiredError*>(&error) && what.find("subcommand") != std::string::npos) {
        std::cerr << "glint: error: a command is required: " << glint::join_words(commands)
                  << " (glint --help)\n";
        return kExitBadInput;
    }
    app.exit(error);
    return kExitBadInput;
}

}  // namespace

static int run(int argc, char** argv) {
    CLI::App app{"glint: a small, fast, correct ray tracer"};
    app.set_version_flag("--version", std::string("glint ") + GLINT_VERSION);
    app.require_subcommand(1);

    RenderOptions options;
    CLI::App* render =
        app.add_subcommand("render", "Render a scene file (or the built-in default scene) to an image");
    render->add_option("scene", options.scene_path,
                       "Scene file: glint's YAML or JSON, or " + glint::importer_formats() +
                           " (by extension); omitted: the built-in default scene");
    render->add_option(
        "-o,--output", options.output,
        "Output image: .png (8-bit sRGB), .pfm or .exr (linear float radiance); default: <scene>.png");
    // The ranges of these four are checked by the scene builder, which says why a value is too large.
    render->add_option("--width", options.flags.width, "Image width in pixels");
    render->add_option("--height", options.flags.height, "Image height in pixels");
    render->add_option("--spp", options.flags.samples_per_pixel, "Samples per pixel");
    render->add_option(
        "--sampler", options.flags.sampler, "Sample pattern (" + [] {
            std::string names;
            for (const auto& n : glint::sampler_table().names()) {
                names += (names.empty() ? "" : ", ") + n;
            }
            return names;
        }() + ")");
    render->add_option(
        "--integrator", options.flags.integrator, "How light is computed (" + [] {
            std::string names;
            for (const auto& n : glint::integrator_table().names()) {
                names += (names.empty() ? "" : ", ") + n;
            }
            return names;
        }() + ")");
    render->add_option("--max-depth", options.flags.max_depth,
                       "Longest path in bounces (whitted, path; at most 1024)");
    render->add_option(
        "--accel", options.flags.accelerator, "Ray accelerator (" + [] {
            std::string names;
            for (const auto& entry : glint::accelerator_table()) {
                names += (names.empty() ? "" : ", ") + entry.name;
            }
            return names;
        }() + "; default bvh)");
    render->add_option("--threads", options.threads, "Worker threads (default: all cores)")
        ->check(CLI::Range(1, 4096));
    render->add_option("--seed", options.flags.seed,
                       "Random seed: the same seed gives the same image, bit for bit");
    render->add_option("--set", options.sets,
                       "Set any scene key, as the file would: key.path=value (repeatable; e.g. "
                       "--set render.samples=64 --set camera.fov=30 --set objects.0.radius=2)");
    render->add_flag("-q,--quiet", options.quiet, "No progress bar and no summary");
    render->add_option("--camera", options.import.camera, "glTF scenes: the camera to look through, by name");
    render->add_option("--crop", options.flags.crop,
                       "Render only the pixels x0 <= x < x1, y0 <= y < y1, written as an image of that size: "
                       "x0,y0,x1,y1 (the same bits as that window of the full render)");
    render->add_option("--exposure", options.flags.exposure,
                       "Exposure in stops for PNG output: radiance × 2^EV before the tone curve (EXR and PFM "
                       "stay linear)");
    render->add_option(
        "--tonemap", options.flags.tonemap,
        "Tone curve for PNG output: clamp (default), reinhard, aces, agx (EXR and PFM stay linear)");
    render
        ->add_option("--time-limit", options.time_limit,
                     "Stop at the end of the pass that crosses this many seconds and write the image "
                     "reached (every pixel with the same samples)")
        ->check(CLI::PositiveNumber);
    add_samples_command(app);
    add_serve_command(app);
    add_info_command(app);
    add_convert_command(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::RuntimeError& e) {  // a subcommand's callback failed; it printed why
        return e.get_exit_code();
    } catch (const CLI::ParseError& e) {
        return command_line_error(app, argc, argv, e);
    }
    if (render->parsed()) {
        return run_render(options);
    }
    return 0;
}

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const glint::SceneError& e) {  // a command that let a scene error through: still bad input
        std::cerr << e.what() << '\n';
        return kExitBadInput;
    } catch (const std::bad_alloc&) {
        std::cerr << "glint: error: out of memory (the scene, image or sample count may be too large for "
                     "this machine)\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "glint: internal error: " << e.what() << '\n';
        return 1;
    } catch (...) {
        std::cerr << "glint: internal error: an unknown exception\n";
        return 1;
    }
}
