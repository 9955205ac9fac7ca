// How fast the preview answers an edit: the time from an edit of `glint serve`'s scene to the first
// frame that shows it, on a scene with a mesh of 262 144 triangles (tests/generated_meshes.hpp). The
// issue's target: a camera edit answers within 100 ms on the 2-core machine (it rebuilds only the view);
// a material edit keeps the shapes and their BVH; a mesh reload (the first build) is for comparison.
//   ./build/release/bench/glint_bench_serve_edit
#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

#include "../tests/generated_meshes.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/serve/preview_session.hpp"

namespace {

constexpr double kCameraEditTargetMs = 100;

std::filesystem::path scene_dir() {
    static const std::filesystem::path dir = [] {
        auto path = std::filesystem::temp_directory_path() / "glint-bench-serve-edit";
        std::filesystem::create_directories(path);
        return path;
    }();
    return dir;
}

// Waits for the first frame of `generation`.
void wait_for(const glint::PreviewSession& session, std::uint64_t generation) {
    std::uint64_t seen = 0;
    for (;;) {
        const auto frame = session.wait_for_frame(seen, std::chrono::seconds(10));
        if (frame && frame->generation >= generation) {
            return;
        }
        seen = frame ? frame->id : 0;
    }
}

glint::SceneEdit edit(std::vector<std::string> path, double value) {
    glint::Node node;
    node.kind = glint::Node::Kind::Scalar;
    node.scalar = std::to_string(value);
    return {std::move(path), node};
}

// Edits `path` to a new value each iteration and times the first frame of the edited scene.
void time_edits(benchmark::State& state, const std::vector<std::string>& path, double first, double step,
                double target_ms) {
    const glint::SceneDesc desc = glint::parse_scene_text(glint::test::large_mesh_scene(scene_dir()),
                                                          (scene_dir() / "scene.yaml").string(), scene_dir());
    glint::PreviewSession session(desc, "scene.yaml");
    wait_for(session, 1);
    double value = first;
    double worst_ms = 0;
    for (auto _ : state) {
        value += step;
        const auto start = std::chrono::steady_clock::now();
        wait_for(session, session.apply({edit(path, value)}));
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        worst_ms = std::max(worst_ms, ms);
        state.SetIterationTime(ms * 1e-3);
    }
    state.counters["worst_ms"] = worst_ms;
    if (target_ms > 0) {
        state.counters["target_ms"] = target_ms;
        if (worst_ms > target_ms) {
            state.SkipWithError("slower than the target");
        }
    }
}

void BM_CameraEdit(benchmark::State& state) {
    time_edits(state, {"camera", "fov"}, 40, 0.5, kCameraEditTargetMs);
}
void BM_MaterialEdit(benchmark::State& state) {
    time_edits(state, {"materials", "clay", "albedo"}, 0.2, 0.01, 0);
}
void BM_FirstBuild(benchmark::State& state) {
    const glint::SceneDesc desc = glint::parse_scene_text(glint::test::large_mesh_scene(scene_dir()),
                                                          (scene_dir() / "scene.yaml").string(), scene_dir());
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        glint::PreviewSession session(desc, "scene.yaml");
        wait_for(session, 1);
        state.SetIterationTime(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
}
BENCHMARK(BM_CameraEdit)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(20);
BENCHMARK(BM_MaterialEdit)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(10);
BENCHMARK(BM_FirstBuild)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
