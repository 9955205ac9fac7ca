// One image over the ranks of an MPI job. Every rank loads and builds the scene; the ranks agree that it
// built everywhere, and the same (a hash of the scene tree and glint's version); then rank 0 hands out
// bands of rows of the image (or of its crop window) one at a time: to each other rank when it returns
// the previous band, and to a render thread of its own. A band is rendered as a crop window, which gives
// exactly the bits of the whole render, so the gathered image is bit for bit that of one `glint render`
// whatever the number of ranks and whoever took which band. Handing bands out on demand balances uneven
// bands (a sky above, glass below) and uneven machines.
//
// Failures: a scene that does not build fails on every rank alike, so rank 0 alone says why (and a rank
// that fails where rank 0 did not says why itself, with its rank and host); every rank then exits with
// the same code. A rank that fails during the render (an exception, running out of memory) calls
// MPI_Abort, and a rank that dies is seen by mpirun, which ends the job: the run fails, it never hangs.
//
// MPI is called from the main thread only (MPI_THREAD_FUNNELED); rank 0's render thread shares nothing
// with it but an atomic band counter and the disjoint rows of the image it fills.
#include "mpi_render.hpp"

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <exception>
#include <iostream>
#include <mutex>
#include <thread>
#include <vector>

#include "glint/image/image_io.hpp"
#include "glint/params/diagnostics.hpp"
#include "glint/scene/scene_checks.hpp"
#include "tile_parts.hpp"

namespace glint::cli {

namespace {

constexpr int kTagBand = 1;    // rank 0 → a rank: the band to render next, or kNoMoreBands
constexpr int kTagTally = 2;   // a rank → rank 0: the band it rendered and its statistics
constexpr int kTagPixels = 3;  // a rank → rank 0: that band's pixels, right after its tally
constexpr int kNoMoreBands = -1;
// Bands per rank: enough that a rank finishing early takes another while a slow band is rendered, few
// enough that a band is many tiles wide (a band is at least one row).
constexpr int kBandsPerRank = 8;

// What a band's render reports, as one message of 64-bit words.
struct BandTally {
    std::int64_t band = 0;
    RayCounters rays;
    std::uint64_t nonfinite = 0;
    std::int64_t first_x = -1, first_y = -1;
    std::uint64_t first_sample = 0;
    std::uint64_t samples_per_pixel = 0;

    static constexpr int kWords = 9;
    std::array<std::uint64_t, kWords> words() const {
        return {static_cast<std::uint64_t>(band),
                rays.camera,
                rays.shadow,
                rays.secondary,
                nonfinite,
                static_cast<std::uint64_t>(first_x),
                static_cast<std::uint64_t>(first_y),
                first_sample,
                samples_per_pixel};
    }
    static BandTally from(const std::array<std::uint64_t, kWords>& w) {
        BandTally t;
        t.band = static_cast<std::int64_t>(w[0]);
        t.rays = RayCounters{w[1], w[2], w[3]};
        t.nonfinite = w[4];
        t.first_x = static_cast<std::int64_t>(w[5]);
        t.first_y = static_cast<std::int64_t>(w[6]);
        t.first_sample = w[7];
        t.samples_per_pixel = w[8];
        return t;
    }
};

std::string host_name() {
    char name[MPI_MAX_PROCESSOR_NAME] = {};
    int length = 0;
    MPI_Get_processor_name(name, &length);
    return std::string(name, static_cast<size_t>(std::max(0, length)));
}

// A message from a rank other than 0 says which rank and host it comes from.
std::string rank_prefix(int rank) {
    return rank == 0 ? "glint: " : "glint: rank " + std::to_string(rank) + " on " + host_name() + ": ";
}

[[noreturn]] void abort_job(int rank, const std::string& why) {
    std::cerr << rank_prefix(rank) << "error: " << why << " (ending the MPI job)" << std::endl;
    MPI_Abort(MPI_COMM_WORLD, 1);
    std::_Exit(1);  // MPI_Abort does not return; this is for the compiler
}

// SIGINT and SIGTERM (mpirun forwards them to every rank) end the rank at once, leaving no temporary
// file: a split render cannot stop "after this pass" on every rank at the same pass.
extern "C" void on_mpi_stop_signal(int signal) {
    remove_pending_temporary_files();
    ::_exit(128 + signal);
}

// The rows of `window` cut into `count` bands, band `index` of them.
PixelWindow band_of_window(const PixelWindow& window, int index, int count) {
    PixelWindow band = band_of(index, count, window.width(), window.height());
    band.x0 += window.x0;
    band.x1 += window.x0;
    band.y0 += window.y0;
    band.y1 += window.y0;
    return band;
}

// Renders one band of the scene into `film` (the whole image's size; bands are disjoint, so a film can
// take one band after another without being cleared) and returns its tally.
BandTally render_band(Scene& scene, Film& film, const PixelWindow& band, int index) {
    scene.view.settings.crop = band;
    const RenderStats stats = render(scene, film);
    BandTally tally;
    tally.band = index;
    tally.rays = stats.rays;
    tally.nonfinite = stats.nonfinite_samples;
    tally.first_x = stats.first_nonfinite_x;
    tally.first_y = stats.first_nonfinite_y;
    tally.first_sample = stats.first_nonfinite_sample;
    tally.samples_per_pixel = stats.samples_per_pixel;
    return tally;
}

// Phase 1 on every rank: the checks, the scene, and the agreement. Returns 0 when every rank may
// render, or the exit code every rank returns.
int prepare_everywhere(const RenderOptions& options, int rank, int ranks, PreparedRender& prepared) {
    int status = 0;
    std::string message;
    if (options.tile) {
        status = kExitBadInput;
        message =
            "error: --tile renders one part in one process; under mpirun the ranks share the image "
            "already (leave --tile out)";
    } else if (options.time_limit > 0) {
        status = kExitBadInput;
        message = "error: --time-limit is not available under mpirun: every rank must take every sample";
    } else if (!options.aov.empty() || !options.checkpoint.empty() || !options.resume.empty()) {
        status = kExitBadInput;
        message =
            "error: --aov, --checkpoint and --resume are not available under mpirun yet: rank 0 gathers "
            "only the image (leave them out, or render in one process)";
    }
    if (status == 0 && rank == 0) {
        try {
            check_output_path(render_output_path(options));
        } catch (const ImageWriteError& e) {
            status = kExitBadInput;
            message = std::string("error: ") + e.what();
        }
    }
    if (status == 0) {
        try {
            prepared = prepare_render(options, rank == 0, true);
        } catch (const SceneError& e) {
            status = kExitBadInput;
            message = e.what();
        } catch (const std::bad_alloc&) {
            status = 1;
            message = "error: out of memory while building the scene";
        } catch (const std::exception& e) {
            status = 1;
            message = std::string("internal error: ") + e.what();
        }
    }
    // Every rank reaches these collectives whatever happened above, so none waits for a rank that gave
    // up. A rank says why only if rank 0 did not already (the same scene fails alike everywhere).
    int rank0_status = status;
    MPI_Bcast(&rank0_status, 1, MPI_INT, 0, MPI_COMM_WORLD);
    int worst = 0;
    MPI_Allreduce(&status, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (status != 0 && (rank == 0 || rank0_status == 0)) {
        const bool positioned = message.rfind("error: ", 0) != 0 && message.rfind("internal", 0) != 0;
        std::cerr << (positioned && rank == 0 ? "" : rank_prefix(rank)) << message << std::endl;
    }
    if (worst != 0) {
        return worst;
    }

    // The same scene on every rank: files that differ between hosts would give an image of two scenes.
    const std::uint64_t hash = prepared.scene_hash;
    std::vector<std::uint64_t> hashes(static_cast<size_t>(ranks));
    MPI_Gather(&hash, 1, MPI_UINT64_T, hashes.data(), 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    int differing_rank = 0;
    if (rank == 0) {
        for (int r = 1; r < ranks && differing_rank == 0; ++r) {
            if (hashes[static_cast<size_t>(r)] != hash) {
                differing_rank = r;
            }
        }
    }
    MPI_Bcast(&differing_rank, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if (differing_rank != 0) {
        if (rank == differing_rank) {
            std::cerr << rank_prefix(rank)
                      << "error: this rank built another scene than rank 0 (the scene file, a file it names "
                         "or glint's version differs between the hosts)"
                      << std::endl;
        }
        return kExitBadInput;
    }
    return 0;
}

// Rank 0: hands out the bands, renders some on a thread of its own, gathers the rest; the whole image.
Image gather_bands(PreparedRender& prepared, const PixelWindow& window, int bands, int ranks, bool progress,
                   RenderStats& stats) {
    Scene& scene = prepared.scene;
    const int width = window.width();
    Image image(width, window.height());
    std::vector<BandTally> tallies(static_cast<size_t>(bands));
    std::atomic<int> next_band{0};
    std::atomic<int> rows_done{0};
    std::mutex tallies_mutex;
    std::exception_ptr local_failure;
    std::atomic<bool> local_finished{false};

    const auto start = std::chrono::steady_clock::now();
    std::thread local([&] {
        try {
            Film film(scene.view.settings.width, scene.view.settings.height);
            for (int band = next_band++; band < bands; band = next_band++) {
                const PixelWindow rows = band_of_window(window, band, bands);
                const BandTally tally = render_band(scene, film, rows, band);
                const Image pixels = film_window(film, rows);
                std::copy(pixels.rgb.begin(), pixels.rgb.end(), image.pixel(0, rows.y0 - window.y0));
                {
                    std::lock_guard lock(tallies_mutex);
                    tallies[static_cast<size_t>(band)] = tally;
                }
                rows_done += rows.height();
            }
        } catch (...) {
            local_failure = std::current_exception();
        }
        local_finished = true;
    });

    const auto next_for = [&](int rank) {
        int band = next_band++;
        if (band >= bands) {
            band = kNoMoreBands;
        }
        MPI_Send(&band, 1, MPI_INT, rank, kTagBand, MPI_COMM_WORLD);
        return band != kNoMoreBands;
    };
    int working = 0;
    for (int r = 1; r < ranks; ++r) {
        working += next_for(r) ? 1 : 0;
    }
    // Progress as a line every tenth: under mpirun the ranks' stderr is a pipe to mpirun, whose own
    // terminal (if any) they cannot see, and a batch job's log reads lines better than a redrawn bar.
    int tenths_said = 0;
    const auto report_progress = [&] {
        const double fraction = static_cast<double>(rows_done) / window.height();
        const int tenths = static_cast<int>(fraction * 10);
        if (progress && tenths > tenths_said && tenths < 10) {
            tenths_said = tenths;
            const double elapsed =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            std::fprintf(stderr, "glint: %d0%% of the image, %.1f s, about %.1f s left\n", tenths, elapsed,
                         elapsed * (1 - fraction) / fraction);
        }
    };
    while (working > 0 || !local_finished) {
        if (local_finished && local_failure) {
            local.join();
            try {
                std::rethrow_exception(local_failure);
            } catch (const std::exception& e) {
                abort_job(0, e.what());
            }
        }
        int arrived = 0;
        MPI_Status status;
        MPI_Iprobe(MPI_ANY_SOURCE, kTagTally, MPI_COMM_WORLD, &arrived, &status);
        if (!arrived) {
            // Sleeping, not spinning: rank 0's render thread (and perhaps other ranks) need the cores.
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
            report_progress();
            continue;
        }
        const int source = status.MPI_SOURCE;
        std::array<std::uint64_t, BandTally::kWords> words{};
        MPI_Recv(words.data(), BandTally::kWords, MPI_UINT64_T, source, kTagTally, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE);
        const BandTally tally = BandTally::from(words);
        if (tally.band < 0 || tally.band >= bands) {
            abort_job(0, "rank " + std::to_string(source) + " returned band " + std::to_string(tally.band) +
                             ", which does not exist");
        }
        const PixelWindow rows = band_of_window(window, static_cast<int>(tally.band), bands);
        MPI_Recv(image.pixel(0, rows.y0 - window.y0), 3 * width * rows.height(), MPI_FLOAT, source,
                 kTagPixels, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        {
            std::lock_guard lock(tallies_mutex);
            tallies[static_cast<size_t>(tally.band)] = tally;
        }
        rows_done += rows.height();
        working -= next_for(source) ? 0 : 1;
    }
    local.join();

    // The statistics, merged in band order: the first non-finite sample is that of the first band
    // that has one.
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats.samples_per_pixel = static_cast<std::uint32_t>(tallies.front().samples_per_pixel);
    for (const BandTally& tally : tallies) {
        stats.rays += tally.rays;
        if (tally.nonfinite > 0 && stats.nonfinite_samples == 0) {
            stats.first_nonfinite_x = static_cast<int>(tally.first_x);
            stats.first_nonfinite_y = static_cast<int>(tally.first_y);
            stats.first_nonfinite_sample = static_cast<std::uint32_t>(tally.first_sample);
        }
        stats.nonfinite_samples += tally.nonfinite;
    }
    return image;
}

// Every other rank: renders the bands rank 0 sends until it sends none.
void render_bands(PreparedRender& prepared, const PixelWindow& window, int bands, int rank) {
    Scene& scene = prepared.scene;
    try {
        Film film(scene.view.settings.width, scene.view.settings.height);
        for (;;) {
            int band = kNoMoreBands;
            MPI_Recv(&band, 1, MPI_INT, 0, kTagBand, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            if (band == kNoMoreBands) {
                return;
            }
            const PixelWindow rows = band_of_window(window, band, bands);
            const auto words = render_band(scene, film, rows, band).words();
            Image pixels = film_window(film, rows);
            MPI_Send(words.data(), BandTally::kWords, MPI_UINT64_T, 0, kTagTally, MPI_COMM_WORLD);
            MPI_Send(pixels.rgb.data(), static_cast<int>(pixels.rgb.size()), MPI_FLOAT, 0, kTagPixels,
                     MPI_COMM_WORLD);
        }
    } catch (const std::bad_alloc&) {
        abort_job(rank, "out of memory while rendering");
    } catch (const std::exception& e) {
        abort_job(rank, e.what());
    }
}

// Rank 0 after the gathering: the warnings, the image, the summary, as `glint render` says them.
int write_gathered(const RenderOptions& options, const PreparedRender& prepared, const Image& image,
                   const RenderStats& stats, int ranks) {
    const RenderSettings& settings = prepared.scene.view.settings;
    const std::filesystem::path output = render_output_path(options);
    print_nonfinite_warning(stats);
    if (all_black(image)) {
        std::fprintf(stderr,
                     "glint: warning: every pixel of the image is black (no light reaches the camera: "
                     "check the lights, the camera's direction and the integrator)\n");
    }
    try {
        write_image(image, output, settings.display);
    } catch (const ImageWriteError& e) {
        std::cerr << "glint: error: " << e.what() << '\n';
        return 1;
    }
    if (!options.quiet) {
        std::fprintf(stderr, "glint: %dx%d, %u spp, %.2f s, %s, %.2f Mrays/s, %d MPI ranks -> %s\n",
                     settings.width, settings.height, stats.samples_per_pixel, stats.seconds,
                     rays_summary(stats.rays).c_str(), stats.mrays_per_second(), ranks,
                     output.string().c_str());
    }
    return 0;
}

}  // namespace

int run_mpi_render(const RenderOptions& options) {
    int provided = 0;
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        std::cerr << "glint: error: MPI_Init failed\n";
        return 1;
    }
    // MPI's default handler aborts the job on any error of an MPI call, which is what a failure of a
    // rank must do here.
    int rank = 0, ranks = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    struct sigaction action {};
    action.sa_handler = on_mpi_stop_signal;
    sigemptyset(&action.sa_mask);
    ::sigaction(SIGINT, &action, nullptr);
    ::sigaction(SIGTERM, &action, nullptr);

    PreparedRender prepared;
    if (const int code = prepare_everywhere(options, rank, ranks, prepared); code != 0) {
        MPI_Finalize();
        return code;
    }
    const RenderSettings& settings = prepared.scene.view.settings;
    const PixelWindow window = settings.rendered_window();
    const int bands = std::min(window.height(), kBandsPerRank * ranks);
    int code = 0;
    if (rank == 0) {
        RenderStats stats;
        Image image;
        try {
            image = gather_bands(prepared, window, bands, ranks, !options.quiet, stats);
        } catch (const std::exception& e) {
            abort_job(0, e.what());
        }
        code = write_gathered(options, prepared, image, stats, ranks);
    } else {
        render_bands(prepared, window, bands, rank);
    }
    MPI_Finalize();
    return code;
}

}  // namespace glint::cli
