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
#include <fstream>
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
#include "glint/render/aov.hpp"
#include "glint/render/checkpoint.hpp"
#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_checks.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"
#include "mpi_render.hpp"
#include "render_setup.hpp"
#include "tile_parts.hpp"

namespace {

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

using glint::cli::kExitBadInput;
using glint::cli::ProgressBar;
using glint::cli::RenderOptions;

int bad_input(const std::string& message) {
    std::cerr << "glint: error: " << message << '\n';
    return kExitBadInput;
}

// --tile I/N: the checks before the render (the part's own, then what a part cannot be combined with).
// Returns the exit code of a refusal, or 0.
int check_tile_options(const RenderOptions& options, const std::filesystem::path& output,
                       std::optional<glint::cli::TileSpec>& tile) {
    if (!options.tile) {
        return 0;
    }
    std::string error;
    tile = glint::cli::parse_tile(*options.tile, error);
    if (!tile) {
        return bad_input("--tile " + *options.tile + ": " + error);
    }
    if (glint::image_format_for(output) != glint::ImageFormat::Exr) {
        return bad_input(
            "--tile writes a part for glint merge, which must be an OpenEXR file (.exr): it "
            "keeps the float values exactly and records the part's place and scene; " +
            output.string() + " is not");
    }
    if (options.flags.crop) {
        return bad_input("--tile and --crop cannot be combined: a part is a band of the whole image");
    }
    if (options.time_limit > 0) {
        return bad_input(
            "--tile and --time-limit cannot be combined: the parts of one image must all "
            "take every sample");
    }
    if (!options.aov.empty() || !options.checkpoint.empty() || !options.resume.empty()) {
        return bad_input(
            "--tile cannot be combined with --aov, --checkpoint or --resume yet: a part carries only "
            "the image");
    }
    return 0;
}

// What an EXR with AOVs records of its render (OpenEXR string attributes; `exrheader` lists them).
glint::ExrAttributes exr_metadata(const glint::cli::PreparedRender& prepared,
                                  const glint::RenderStats& stats) {
    const glint::RenderSettings& settings = prepared.scene.view.settings;
    char seconds[32];
    std::snprintf(seconds, sizeof(seconds), "%.3f", stats.seconds);
    std::string camera = prepared.camera_yaml;
    while (!camera.empty() && camera.back() == '\n') {
        camera.pop_back();
    }
    return {{"glintVersion", GLINT_VERSION},
            {"glintCamera", camera},
            {"glintSpp", std::to_string(stats.samples_per_pixel)},
            {"glintSeed", std::to_string(settings.seed)},
            {"glintRenderSeconds", seconds}};
}

// --aov: the list checked, and an output that can hold float layers.
int check_aov_options(const RenderOptions& options, const std::filesystem::path& output,
                      glint::AovRequest& request) {
    if (options.aov.empty()) {
        return 0;
    }
    try {
        request = glint::parse_aov_list(options.aov);
    } catch (const std::invalid_argument& e) {
        return bad_input(std::string("--aov: ") + e.what());
    }
    if (glint::image_format_for(output) == glint::ImageFormat::Png) {
        return bad_input(
            "--aov needs linear float output: -o NAME.exr (one file, the AOVs as layers) or "
            "-o NAME.pfm (a file per AOV beside it); " +
            output.string() + " is a PNG");
    }
    return 0;
}

// The film of a checkpoint to resume (--resume), checked against the render about to start.
int read_resume_checkpoint(const std::string& path, std::uint64_t fingerprint, const glint::View& view,
                           std::optional<glint::Checkpoint>& checkpoint) {
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) {
        return bad_input(path + ": cannot read the checkpoint (" + error.message() + ")");
    }
    // Checked before anything is read: a checkpoint of this render has exactly this many bytes.
    const std::uint64_t expected = glint::checkpoint_file_bytes(view.settings.width, view.settings.height);
    if (size != expected) {
        return bad_input(path + ": it is " + std::to_string(size) + " bytes long; a checkpoint of this " +
                         std::to_string(view.settings.width) + " x " + std::to_string(view.settings.height) +
                         " render has " + std::to_string(expected));
    }
    std::ifstream in(path, std::ios::binary);
    std::vector<unsigned char> bytes(size);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size))) {
        return bad_input(path + ": cannot read the checkpoint");
    }
    try {
        checkpoint = glint::decode_checkpoint(bytes, path);
        glint::check_checkpoint_matches(*checkpoint, path, fingerprint, view.settings.width,
                                        view.settings.height, view.sampler->samples_per_pixel());
    } catch (const glint::CheckpointError& e) {
        std::cerr << e.what() << '\n';
        return kExitBadInput;
    }
    return 0;
}

// Writes the render's state to `path` atomically; a failure is a warning, not the end of the render.
void write_checkpoint(const std::string& path, std::uint64_t fingerprint, std::uint32_t samples_done,
                      std::uint32_t samples_asked, const glint::Film& film) {
    try {
        glint::write_file_atomically(
            path, glint::encode_checkpoint(fingerprint, samples_done, samples_asked, film));
    } catch (const glint::ImageWriteError& e) {
        std::cerr << "glint: warning: could not write the checkpoint: " << e.what() << '\n';
    }
}

// The AOV layers beside the image: in the EXR itself, or a PFM each (out.albedo.pfm, …).
void write_aovs_as_pfm(const std::filesystem::path& output, const std::vector<glint::ImageLayer>& layers) {
    for (const glint::ImageLayer& layer : layers) {
        std::filesystem::path path = output;
        path.replace_extension("." + layer.name + output.extension().string());
        glint::write_file_atomically(path, glint::encode_pfm(layer));
    }
}

int run_render(const RenderOptions& options) {
    // Check the output path before spending time on the render.
    const std::filesystem::path output = glint::cli::render_output_path(options);
    try {
        glint::check_output_path(output);
    } catch (const glint::ImageWriteError& e) {
        return bad_input(e.what());
    }
    std::optional<glint::cli::TileSpec> tile;
    if (const int refused = check_tile_options(options, output, tile); refused != 0) {
        return refused;
    }
    glint::AovRequest aovs;
    if (const int refused = check_aov_options(options, output, aovs); refused != 0) {
        return refused;
    }

    install_stop_handlers();
    glint::cli::PreparedRender prepared;
    try {
        prepared = glint::cli::prepare_render(options, true, glint::cli::needs_scene_hash(options));
    } catch (const glint::SceneError& e) {
        std::cerr << e.what() << '\n';
        return kExitBadInput;
    }
    glint::Scene& scene = prepared.scene;
    glint::RenderSettings& settings = scene.view.settings;
    if (tile) {
        if (settings.crop) {
            return bad_input(
                "--tile cannot be combined with render.crop: a part is a band of the whole image");
        }
        if (tile->count > settings.height) {
            return bad_input("--tile " + *options.tile + ": the image has only " +
                             std::to_string(settings.height) + " rows, fewer than " +
                             std::to_string(tile->count) + " parts");
        }
        settings.crop = glint::cli::band_of(tile->index, tile->count, settings.width, settings.height);
    }
    if (g_stop_after_pass.load()) {
        std::cerr << "glint: interrupted before rendering; no image written\n";
        return kExitInterrupted;
    }

    glint::Film film(settings.width, settings.height);
    glint::RenderCallbacks callbacks;
    const std::uint32_t samples_asked = scene.view.sampler->samples_per_pixel();
    if (!options.resume.empty()) {
        std::optional<glint::Checkpoint> checkpoint;
        if (const int refused =
                read_resume_checkpoint(options.resume, prepared.scene_hash, scene.view, checkpoint);
            refused != 0) {
            return refused;
        }
        film = std::move(checkpoint->film);
        callbacks.resume_after_samples = checkpoint->samples_done;
        if (!options.quiet) {
            std::fprintf(stderr, "glint: resuming %s from %u of %u samples per pixel\n",
                         options.resume.c_str(), checkpoint->samples_done, samples_asked);
        }
    }
    auto last_checkpoint = std::chrono::steady_clock::now();
    if (!options.checkpoint.empty()) {
        // At the end of a pass (the film then holds the same samples in every pixel), once the interval
        // has passed since the last one; and below, when the render stops early.
        callbacks.pass_done = [&](const glint::Film& rendered, std::uint32_t samples_done) {
            const auto now = std::chrono::steady_clock::now();
            if (samples_done < samples_asked &&
                std::chrono::duration<double>(now - last_checkpoint).count() >= options.checkpoint_every) {
                write_checkpoint(options.checkpoint, prepared.scene_hash, samples_done, samples_asked,
                                 rendered);
                last_checkpoint = now;
            }
        };
    }
    ProgressBar bar(!options.quiet && ::isatty(STDERR_FILENO));
    callbacks.progress = [&bar](double fraction) { bar.update(fraction); };
    callbacks.stop_after_pass = &g_stop_after_pass;
    callbacks.time_limit_seconds = options.time_limit;
    const glint::RenderStats stats = glint::render(scene, film, callbacks);
    bar.finish();
    const bool finished = !stats.cancelled && !stats.time_limit_reached;
    if (!options.checkpoint.empty() && !finished && stats.samples_per_pixel > 0 &&
        stats.samples_per_pixel < samples_asked) {
        write_checkpoint(options.checkpoint, prepared.scene_hash, stats.samples_per_pixel, samples_asked,
                         film);
        std::fprintf(stderr, "glint: checkpoint %s holds %u of %u samples per pixel (--resume %s goes on)\n",
                     options.checkpoint.c_str(), stats.samples_per_pixel, samples_asked,
                     options.checkpoint.c_str());
    }

    glint::cli::print_nonfinite_warning(stats);
    // Only the window was rendered (a crop or a part): it is written alone.
    const glint::Image image =
        settings.crop ? glint::cli::film_window(film, *settings.crop) : film.to_image();
    if (glint::all_black(image) && !stats.cancelled) {
        std::fprintf(stderr,
                     "glint: warning: every %s is black (no light reaches the camera: "
                     "check the lights, the camera's direction and the integrator)\n",
                     tile ? "pixel of this part" : "pixel of the image");
    }
    try {
        if (tile) {
            glint::cli::PartInfo part;
            part.version = GLINT_VERSION;
            part.tile = *tile;
            part.window = *settings.crop;
            part.width = settings.width;
            part.height = settings.height;
            part.seed = settings.seed;
            part.samples_per_pixel = stats.samples_per_pixel;
            part.scene_hash = prepared.scene_hash;
            part.display = settings.display;
            glint::write_file_atomically(output, glint::encode_exr(image, glint::cli::part_attributes(part)));
        } else if (aovs.any()) {
            const std::vector<glint::ImageLayer> layers = glint::render_aovs(
                *scene.world, scene.view, film, settings.rendered_window(), stats.samples_per_pixel, aovs);
            if (glint::image_format_for(output) == glint::ImageFormat::Exr) {
                glint::write_file_atomically(output,
                                             glint::encode_exr(image, exr_metadata(prepared, stats), layers));
            } else {
                write_aovs_as_pfm(output, layers);
                glint::write_image(image, output, settings.display);
            }
        } else {
            glint::write_image(image, output, settings.display);
        }
    } catch (const glint::ImageWriteError& e) {
        std::cerr << "glint: error: " << e.what() << '\n';
        return 1;
    }
    if (finished && !options.checkpoint.empty()) {
        // The image has every sample: the checkpoint has served its purpose.
        std::error_code ignored;  // already gone is fine
        std::filesystem::remove(options.checkpoint, ignored);
    }
    if (stats.cancelled) {
        // Each pixel is the mean of the samples it has: an unfinished render, not a darker one.
        std::fprintf(stderr, "glint: interrupted: wrote %s with %u of %u samples per pixel\n",
                     output.string().c_str(), stats.samples_per_pixel, settings.samples_per_pixel);
        return kExitInterrupted;
    }
    if (stats.time_limit_reached) {
        // Not an error: the image is what the time allowed, every pixel with the same samples.
        std::fprintf(stderr, "glint: time limit of %g s reached: %s has %u of %u samples per pixel\n",
                     options.time_limit, output.string().c_str(), stats.samples_per_pixel,
                     settings.samples_per_pixel);
    }
    if (!options.quiet) {
        const std::string part = tile ? " part " + *options.tile + " (rows " +
                                            std::to_string(settings.crop->y0) + "-" +
                                            std::to_string(settings.crop->y1 - 1) + ")"
                                      : "";
        std::fprintf(stderr, "glint: %dx%d%s, %u spp, %.2f s, %s, %.2f Mrays/s -> %s\n", settings.width,
                     settings.height, part.c_str(), stats.samples_per_pixel, stats.seconds,
                     glint::cli::rays_summary(stats.rays).c_str(), stats.mrays_per_second(),
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
    render->add_option("--tile", options.tile,
                       "Render only part I of N (numbered from 0), a band of rows, into an .exr file that "
                       "glint merge puts together with the others: I/N (docs/distributed.md)");
    render->add_option("--exposure", options.flags.exposure,
                       "Exposure in stops for PNG output: radiance × 2^EV before the tone curve (EXR and PFM "
                       "stay linear)");
    render->add_option(
        "--tonemap", options.flags.tonemap,
        "Tone curve for PNG output: clamp (default), reinhard, aces, agx (EXR and PFM stay linear)");
    render->add_option(
        "--aov", options.aov,
        "Extra layers for denoisers and compositing, comma-separated: albedo, normal, depth, spp, "
        "variance (in the .exr as layers, or beside a .pfm as NAME.albedo.pfm, …)");
    render->add_option("--checkpoint", options.checkpoint,
                       "Write the render's state to this file every --checkpoint-every seconds and when it "
                       "stops early (Ctrl-C, --time-limit); removed once the image is complete");
    render
        ->add_option("--checkpoint-every", options.checkpoint_every,
                     "Seconds between checkpoints (default 60; at the end of a pass)")
        ->check(CLI::PositiveNumber);
    render->add_option("--resume", options.resume,
                       "Go on from this checkpoint: the same command line gives the bits of a render that "
                       "never stopped");
    render
        ->add_option("--time-limit", options.time_limit,
                     "Stop at the end of the pass that crosses this many seconds and write the image "
                     "reached (every pixel with the same samples)")
        ->check(CLI::PositiveNumber);
    add_samples_command(app);
    add_serve_command(app);
    add_info_command(app);
    add_convert_command(app);
    add_merge_command(app);

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
        if (glint::cli::launched_by_mpi()) {
#ifdef GLINT_HAVE_MPI
            return glint::cli::run_mpi_render(options);
#else
            if (glint::cli::launched_ranks() > 1) {
                return bad_input(
                    "started by an MPI launcher with " + std::to_string(glint::cli::launched_ranks()) +
                    " processes, but this glint was built without MPI (libopenmpi-dev was not found "
                    "when it was configured): each process would render the whole image");
            }
#endif
        }
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
