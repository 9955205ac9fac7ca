// Whole-scene benchmark: the built-in default scene at a fixed size and sample count, on all cores.
// Reports Mrays/s (camera + shadow rays) as the counter "Mrays/s".
//   ./build/release/bench/glint_bench_scene
#include <benchmark/benchmark.h>

#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"

namespace {

void BM_DefaultScene(benchmark::State& state) {
    glint::RenderFlags overrides;
    overrides.width = 640;
    overrides.height = 360;
    overrides.samples_per_pixel = 16;
    const glint::Scene scene = glint::build_scene(glint::default_scene(), overrides);
    std::uint64_t rays = 0;
    for (auto _ : state) {
        glint::Film film(scene.view.settings.width, scene.view.settings.height);
        const glint::RenderStats stats = glint::render(scene, film);
        rays += stats.rays.total();
        benchmark::DoNotOptimize(film.pixel(0, 0));
    }
    state.counters["Mrays/s"] =
        benchmark::Counter(static_cast<double>(rays) * 1e-6, benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DefaultScene)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
