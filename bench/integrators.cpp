// Whole-scene benchmarks of the integrators, on all cores. Each reports wall time per image and Mrays/s
// (camera + shadow + secondary rays).
//   ./build/release/bench/glint_bench_integrators                  smallpt at 256×192
//   ./build/release/bench/glint_bench_integrators --smallpt-full   smallpt at its own 1024×768
//
// - CornellBox/path: examples/cornell-box.yaml, 256×256, 16 spp, max depth 8.
// - RtiowFinal/path: the final scene of Ray Tracing in One Weekend (examples/rtiow-final.yaml) at the
//   book's 400×225, 32 spp, max depth 50.
// - Smallpt/path: examples/smallpt.yaml at 64 spp (smallpt's `./smallpt 64`), 256×192 unless
//   --smallpt-full asks for smallpt's 1024×768.
// The fastest accelerator in the table is used ("bvh" when present, else "list").
#include <benchmark/benchmark.h>

#include <cstring>
#include <string>

#include "glint/params/diagnostics.hpp"
#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"

namespace {

bool smallpt_full = false;

std::string best_accelerator() {
    for (const auto& entry : glint::accelerator_table()) {
        if (entry.name == "bvh") {
            return "bvh";
        }
    }
    return "list";
}

void render_example(benchmark::State& state, const std::string& file, int width, int height,
                    std::uint32_t spp, int max_depth) {
    glint::RenderFlags overrides;
    overrides.width = width;
    overrides.height = height;
    overrides.samples_per_pixel = spp;
    overrides.max_depth = max_depth;
    overrides.integrator = "path";
    overrides.accelerator = best_accelerator();
    glint::Scene scene;
    try {
        scene = glint::build_scene(
            glint::load_scene_file(std::string(GLINT_SOURCE_DIR) + "/examples/" + file), overrides);
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
        return;
    }
    std::uint64_t rays = 0;
    for (auto _ : state) {
        glint::Film film(scene.view.settings.width, scene.view.settings.height);
        const glint::RenderStats stats = glint::render(scene, film);
        rays += stats.rays.total();
        benchmark::DoNotOptimize(film.pixel(0, 0));
    }
    state.counters["Mrays/s"] =
        benchmark::Counter(static_cast<double>(rays) * 1e-6, benchmark::Counter::kIsRate);
    state.SetLabel(std::to_string(width) + "x" + std::to_string(height) + ", " + std::to_string(spp) +
                   " spp, " + overrides.accelerator.value());
}

void BM_CornellBox(benchmark::State& state) {
    render_example(state, "cornell-box.yaml", 256, 256, 16, 8);
}
void BM_RtiowFinal(benchmark::State& state) {
    render_example(state, "rtiow-final.yaml", 400, 225, 32, 50);
}
void BM_Smallpt(benchmark::State& state) {
    if (smallpt_full) {
        render_example(state, "smallpt.yaml", 1024, 768, 64, 50);
    } else {
        render_example(state, "smallpt.yaml", 256, 192, 64, 50);
    }
}
BENCHMARK(BM_CornellBox)
    ->Name("CornellBox/path")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(BM_RtiowFinal)
    ->Name("RtiowFinal/path")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(BM_Smallpt)->Name("Smallpt/path")->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
    // Our own flag first; Google Benchmark rejects flags it does not know.
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--smallpt-full") == 0) {
            smallpt_full = true;
        } else {
            argv[kept++] = argv[i];
        }
    }
    argc = kept;
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) {
        return 1;
    }
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
