// Time to reach a given error: the path-traced Cornell box against a high-sample reference.
//   ./build/release/bench/glint_bench_cornell_rmse [--size 96] [--reference-spp 1024] [--target 0.05]
//
// Renders the reference (seed 1), then the same view with another seed at 1, 2, 4, … spp, and prints
// for each the wall time, Mrays/s and the RMSE against the reference relative to the reference's mean
// radiance. The time to reach the target relative RMSE is interpolated in log–log between the two
// sample counts around it (Monte Carlo RMSE falls as spp^-1/2, a straight line there). The reference's
// own noise is ~ sqrt(spp/reference_spp) of each estimate's, so targets well above it are meaningful.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"

namespace {

struct Run {
    glint::Film film;
    glint::RenderStats stats;
};

Run render_cornell(int size, std::uint32_t spp, std::uint64_t seed) {
    glint::RenderFlags overrides;
    overrides.width = size;
    overrides.height = size;
    overrides.samples_per_pixel = spp;
    overrides.seed = seed;
    overrides.integrator = "path";
    overrides.max_depth = 8;
    overrides.sampler = "sobol";
    const glint::Scene scene = glint::build_scene(
        glint::load_scene_file(std::string(GLINT_SOURCE_DIR) + "/examples/cornell-box.yaml"), overrides);
    Run run{glint::Film(size, size), {}};
    run.stats = glint::render(scene, run.film);
    return run;
}

}  // namespace

int main(int argc, char** argv) {
    int size = 96;
    std::uint32_t reference_spp = 1024;
    double target = 0.05;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (std::strcmp(argv[i], "--size") == 0) {
            size = std::stoi(argv[i + 1]);
        } else if (std::strcmp(argv[i], "--reference-spp") == 0) {
            reference_spp = static_cast<std::uint32_t>(std::stoul(argv[i + 1]));
        } else if (std::strcmp(argv[i], "--target") == 0) {
            target = std::stod(argv[i + 1]);
        } else {
            std::fprintf(stderr, "unknown argument %s\n", argv[i]);
            return 2;
        }
    }
    const Run reference = render_cornell(size, reference_spp, 1);
    double mean = 0;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            mean += reference.film.pixel(x, y).luminance();
        }
    }
    mean /= size * size;
    std::printf(
        "Cornell box %dx%d, path, max depth 8, sobol; reference %u spp in %.2f s (%.2f Mrays/s), mean %.4f\n",
        size, size, reference_spp, reference.stats.seconds, reference.stats.mrays_per_second(), mean);
    std::printf("%8s %10s %10s %14s\n", "spp", "seconds", "Mrays/s", "relative RMSE");
    double previous_time = 0, previous_error = 0;
    bool reached = false;
    for (std::uint32_t spp = 1; spp <= reference_spp / 8; spp *= 2) {
        const Run run = render_cornell(size, spp, 2);
        double squared = 0;
        for (int y = 0; y < size; ++y) {
            for (int x = 0; x < size; ++x) {
                const glint::Rgb d = run.film.pixel(x, y) - reference.film.pixel(x, y);
                squared += d.r * d.r + d.g * d.g + d.b * d.b;
            }
        }
        const double error = std::sqrt(squared / (3.0 * size * size)) / mean;
        std::printf("%8u %10.3f %10.2f %14.4f\n", spp, run.stats.seconds, run.stats.mrays_per_second(),
                    error);
        if (!reached && error <= target) {
            reached = true;
            double seconds = run.stats.seconds;
            if (previous_error > target) {
                const double f = std::log(previous_error / target) / std::log(previous_error / error);
                seconds = std::exp(std::log(previous_time) +
                                   f * (std::log(run.stats.seconds) - std::log(previous_time)));
            }
            std::printf("time to reach relative RMSE %.3f: %.3f s\n", target, seconds);
        }
        previous_time = run.stats.seconds;
        previous_error = error;
    }
    if (!reached) {
        std::printf("relative RMSE %.3f not reached below %u spp\n", target, reference_spp / 8);
    }
    return 0;
}
