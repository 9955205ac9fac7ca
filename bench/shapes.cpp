// Ray–shape intersection cost per shape: the same 4096 random rays (about half of them hit) against each
// analytic shape and an instance, single-threaded. Reports ns per ray; compare shapes within one run.
//   ./build/release/bench/glint_bench_shapes
#include <benchmark/benchmark.h>

#include <functional>
#include <memory>
#include <vector>

#include "glint/core/hash.hpp"
#include "glint/geometry/box.hpp"
#include "glint/geometry/cone.hpp"
#include "glint/geometry/cylinder.hpp"
#include "glint/geometry/disk.hpp"
#include "glint/geometry/instance.hpp"
#include "glint/geometry/rectangle.hpp"
#include "glint/geometry/sphere.hpp"
#include "glint/geometry/torus.hpp"

namespace {

using namespace glint;

// Rays from a sphere of radius 3 around the origin towards random points of the box [−1, 1]³.
std::vector<Ray> make_rays() {
    std::vector<Ray> rays;
    for (std::uint32_t i = 0; i < 4096; ++i) {
        const SampleKey key{5, i, 0, 0};
        const double z = 1 - 2 * key.uniform(0), r = std::sqrt(std::max(0.0, 1 - z * z)),
                     phi = 2 * kPi * key.uniform(1);
        const Vec3 origin = 3.0 * Vec3{r * std::cos(phi), r * std::sin(phi), z};
        const Vec3 target{2 * key.uniform(2) - 1, 2 * key.uniform(3) - 1, 2 * key.uniform(4) - 1};
        rays.push_back({origin, target - origin});
    }
    return rays;
}

void run(benchmark::State& state, const Shape& shape) {
    const std::vector<Ray> rays = make_rays();
    std::int64_t hits = 0;
    for (auto _ : state) {
        for (const Ray& ray : rays) {
            Hit hit;
            hits += shape.intersect(ray, kInf, hit);
            benchmark::DoNotOptimize(hit);
        }
    }
    const double total = static_cast<double>(state.iterations()) * static_cast<double>(rays.size());
    state.SetItemsProcessed(static_cast<std::int64_t>(total));
    state.counters["hit fraction"] = static_cast<double>(hits) / total;
}

void BM_Sphere(benchmark::State& s) {
    run(s, Sphere({0, 0, 0}, 1));
}
void BM_Disk(benchmark::State& s) {
    run(s, Disk({0, 0, 0}, {0.2, 1, 0.3}, 1));
}
void BM_Rectangle(benchmark::State& s) {
    run(s, Rectangle({-1, 0, -1}, {2, 0.2, 0}, {0, 0.3, 2}));
}
void BM_Box(benchmark::State& s) {
    run(s, Box({-0.8, -0.8, -0.8}, {0.8, 0.8, 0.8}));
}
void BM_Cylinder(benchmark::State& s) {
    run(s, Cylinder({0, -1, 0}, {0.2, 1, 0.1}, 0.8, true));
}
void BM_Cone(benchmark::State& s) {
    run(s, Cone({0, -1, 0}, {0.2, 1, 0.1}, 0.9, true));
}
void BM_Torus(benchmark::State& s) {
    run(s, Torus({0, 0, 0}, {0.3, 1, 0.2}, 0.7, 0.3));
}
void BM_EllipsoidInstance(benchmark::State& s) {
    run(s, Instance(std::make_unique<Sphere>(Vec3{}, 1),
                    Transform::scale({1, 0.6, 0.8})->then(Transform::rotate({1, 1, 0}, 30))));
}
BENCHMARK(BM_Sphere);
BENCHMARK(BM_Disk);
BENCHMARK(BM_Rectangle);
BENCHMARK(BM_Box);
BENCHMARK(BM_Cylinder);
BENCHMARK(BM_Cone);
BENCHMARK(BM_Torus);
BENCHMARK(BM_EllipsoidInstance);

}  // namespace

BENCHMARK_MAIN();
