// Ray accelerators raced: glint's BVH against Embree, single rays, 2 threads, on the bunny (69 k
// triangles), the dragon subdivided to 1.6 M triangles, and 100 k spheres; for each, primary rays,
// diffuse-bounce rays (cosine-distributed from the primary hits) and shadow rays (towards a point
// light). Also book 2's Cornell box (examples/rtiow-cornell.yaml: quads and two transformed boxes), with
// the rays a render of it traces: its camera's, a bounce from each hit and shadow rays to points of its
// light; and `Rays/cornell/render/bvh`, the rays of a glint render of it replayed in the order the render
// traced them (below: "A render's own rays, replayed"), so that bench-peers can set its whole-render rate
// against this kernel rate (--render-scene=NAME=FILE replays a render of another scene file,
// --render-spp=N sets the recorded render's samples a pixel, 16 by default). Also: BVH build rate and
// bytes per triangle, and how the cost per ray grows from 1 k to 1 M triangles (UV spheres of exactly 1 024
// and 1 048 576 triangles; also 2 k to 2 M, subdivided octahedra, whose triangles are roughly uniform, no
// slivers at the poles). Ratios are printed at the end of the run, from the medians when the runs are
// repeated:
//   ./build/release/bench/glint_bench_accel [--benchmark_repetitions=3]
//
// On a machine whose speed drifts from one second to the next (a shared VM), one run's ratio can be
// off by 20 %. `--pairs=N` races the two instead in N rounds: in each, glint's BVH and Embree trace
// the same ray set back to back, in alternating order, and the round gives one ratio; it prints the
// median of each ray set's N ratios with a 95 % interval (order statistics of the median, no assumption
// on the noise's distribution). `--embree-config=STRING` passes STRING to Embree's rtcNewDevice:
// Embree uses its AVX-512 kernels where the CPU has them, glint's traversal AVX2, so `isa=avx2` races
// like with like. `--benchmark_filter` selects the ray sets in both modes:
//   ./build/release/bench/glint_bench_accel --pairs=15 --benchmark_filter='Rays/(bunny|dragon1.6M)/diffuse'
//
// The bunny and the dragon are optional data (not in the repository): they are read from
// $GLINT_DATA_DIR/meshes, else from the shared/data folder beside the repository. When they are not
// there, generated meshes of similar size stand in, under their own names (blob82k, blob1.3M: a bumpy
// closed surface, the second subdivided twice like the dragon), and a note says so.
#include <benchmark/benchmark.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cassert>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <regex>
#include <span>
#include <stdexcept>

#include "glint/accel/bvh.hpp"
#include "glint/accel/embree.hpp"
#include "glint/core/frame.hpp"
#include "glint/geometry/mesh.hpp"
#include "glint/geometry/sphere.hpp"
#include "glint/light/area.hpp"
#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"

namespace {

using namespace glint;

constexpr int kThreads = 2;
constexpr std::size_t kRaysPerSet = 1 << 16;

// --embree-config: Embree's device configuration (empty: its defaults).
std::string embree_config;

// One of the three kinds of query; shadow rays ask occluded() with t_max = 1 (the light).
struct RaySet {
    std::vector<Ray> rays;
    bool shadow = false;
};

struct BenchScene {
    std::vector<std::unique_ptr<Shape>> shapes;
    std::shared_ptr<const World> world;  // a scene file's world, whose shapes are raced instead
    std::vector<const Shape*> pointers;
    std::unique_ptr<Accelerator> bvh, embree;
    std::map<std::string, RaySet> ray_sets;  // "primary", "diffuse", "shadow"
    std::size_t triangles = 0;
};

// Midpoint subdivision: every triangle becomes four (positions only; the surface is unchanged).
MeshData subdivide(const MeshData& in) {
    MeshData out;
    out.positions = in.positions;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
        const auto [it, inserted] =
            midpoint.try_emplace(std::minmax(a, b), static_cast<std::uint32_t>(out.positions.size()));
        if (inserted) {
            out.positions.push_back(0.5 * (out.positions[a] + out.positions[b]));
        }
        return it->second;
    };
    for (const auto& t : in.triangles) {
        const std::uint32_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
        out.triangles.push_back({t[0], ab, ca});
        out.triangles.push_back({ab, t[1], bc});
        out.triangles.push_back({ca, bc, t[2]});
        out.triangles.push_back({ab, bc, ca});
    }
    return out;
}

// A unit sphere of exactly 2 · segments · (rings − 1) triangles: `rings` + 1 circles of latitude
// (the poles included), `segments` meridians, a fan of triangles at each pole and quads between.
MeshData uv_sphere(std::uint32_t segments, std::uint32_t rings) {
    assert(segments >= 3 && rings >= 2);
    MeshData mesh;
    mesh.positions.push_back({0, 1, 0});
    for (std::uint32_t r = 1; r < rings; ++r) {
        const double theta = kPi * r / rings;
        for (std::uint32_t s = 0; s < segments; ++s) {
            const double phi = 2 * kPi * s / segments;
            mesh.positions.push_back(
                {std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)});
        }
    }
    mesh.positions.push_back({0, -1, 0});
    const auto ring_vertex = [&](std::uint32_t r, std::uint32_t s) {
        return 1 + (r - 1) * segments + s % segments;
    };
    const auto south = static_cast<std::uint32_t>(mesh.positions.size() - 1);
    for (std::uint32_t s = 0; s < segments; ++s) {
        mesh.triangles.push_back({0, ring_vertex(1, s + 1), ring_vertex(1, s)});
        for (std::uint32_t r = 1; r + 1 < rings; ++r) {
            mesh.triangles.push_back({ring_vertex(r, s), ring_vertex(r, s + 1), ring_vertex(r + 1, s + 1)});
            mesh.triangles.push_back({ring_vertex(r, s), ring_vertex(r + 1, s + 1), ring_vertex(r + 1, s)});
        }
        mesh.triangles.push_back({south, ring_vertex(rings - 1, s), ring_vertex(rings - 1, s + 1)});
    }
    return mesh;
}

MeshData tessellated_sphere(int subdivisions) {
    MeshData mesh;
    mesh.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    mesh.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (int s = 0; s < subdivisions; ++s) {
        mesh = subdivide(mesh);
        for (Vec3& p : mesh.positions) {
            p = normalize(p);
        }
    }
    return mesh;
}

// A bumpy closed surface, the bunny's stand-in: a subdivided icosahedron (20 · 4^s triangles, vertices
// shared) whose radius is displaced by sine waves, so that it is not convex and shadows itself.
MeshData bumpy_blob(int subdivisions) {
    MeshData mesh;
    const double g = (1 + std::sqrt(5.0)) / 2;
    mesh.positions = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                      {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    mesh.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int s = 0; s < subdivisions; ++s) {
        mesh = subdivide(mesh);
        for (Vec3& p : mesh.positions) {
            p = normalize(p);
        }
    }
    for (Vec3& p : mesh.positions) {
        const double r = 1 + 0.20 * std::sin(5 * p.x + 1) * std::sin(4 * p.y) +
                         0.12 * std::sin(9 * p.z + 2 * p.x) + 0.06 * std::sin(15 * p.y + 7 * p.z + 0.5);
        p = Vec3{0.08 * r * p.x, 0.068 * r * p.y, 0.056 * r * p.z};
    }
    return mesh;
}

// The optional meshes: $GLINT_DATA_DIR/meshes, else shared/data/meshes beside the repository.
std::filesystem::path data_dir() {
    const char* from_environment = std::getenv("GLINT_DATA_DIR");
    return from_environment != nullptr && *from_environment != '\0'
               ? std::filesystem::path(from_environment)
               : std::filesystem::path(GLINT_SHARED_DIR) / "data";
}

// A mesh the races use: a Stanford model when its file is there, else a generated one of similar size.
struct MeshSource {
    std::string name;  // in the benchmarks' names
    std::function<MeshData()> make;
    std::string note;  // what stands in for what, when the file is missing
};

MeshSource mesh_source(const std::string& file, const std::string& name,
                       std::function<MeshData(MeshData)> finish, const std::string& stand_in_name,
                       int stand_in_subdivisions) {
    const std::filesystem::path path = data_dir() / "meshes" / file;
    std::error_code error;
    if (std::filesystem::is_regular_file(path, error)) {
        return {name, [path, finish] { return finish(load_mesh_file(path)); }, ""};
    }
    return {stand_in_name,
            [finish, stand_in_subdivisions] { return finish(bumpy_blob(stand_in_subdivisions)); },
            "note: " + path.string() + " is absent (set GLINT_DATA_DIR to a folder with meshes/): '" +
                stand_in_name + "', a generated mesh of similar size, stands in for '" + name + "'"};
}

// The bunny (69 451 triangles) or a 81 920-triangle blob.
const MeshSource& small_mesh() {
    static const MeshSource source = mesh_source(
        "stanford-bunny.obj", "bunny", [](MeshData m) { return m; }, "blob82k", 6);
    return source;
}

// The dragon subdivided twice (1.6 M triangles), or the blob subdivided twice (1.3 M).
const MeshSource& large_mesh() {
    static const MeshSource source = mesh_source(
        "dragon_100k_vcg.ply", "dragon1.6M", [](MeshData m) { return subdivide(subdivide(m)); }, "blob1.3M",
        6);
    return source;
}

// The three ray sets: `camera(x, y)` gives the primary ray of each pixel of an image of width × height
// = kRaysPerSet pixels, `light(u, v)` the point of the light that a shadow ray from the pixel's hit
// goes to.
void make_rays(BenchScene& scene, int width, const std::function<Ray(int, int)>& camera,
               const std::function<Vec3(double, double)>& light) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0, 1);
    RaySet primary, diffuse, shadow;
    shadow.shadow = true;
    const int height = static_cast<int>(kRaysPerSet / static_cast<std::size_t>(width));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const Ray ray = camera(x, y);
            primary.rays.push_back(ray);
            Hit hit;
            if (!scene.bvh->intersect(ray, kInf, hit)) {
                continue;
            }
            const Vec3 n = dot(hit.normal, ray.direction) < 0 ? hit.normal : -hit.normal;
            // Cosine-distributed about the normal (Malley's method).
            const double r = std::sqrt(u(rng)), phi = 2 * kPi * u(rng);
            const Frame local = Frame::from_normal(n);
            const Vec3 bounce =
                local.to_world({r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - r * r))});
            diffuse.rays.push_back(spawn_ray(hit, bounce));
            const double lu = u(rng), lv = u(rng);
            shadow.rays.push_back(spawn_ray_to(hit, light(lu, lv)));
        }
    }
    scene.ray_sets["primary"] = std::move(primary);
    scene.ray_sets["diffuse"] = std::move(diffuse);
    scene.ray_sets["shadow"] = std::move(shadow);
}

// The rays of a generated scene: a camera on a diagonal, looking at the centre, its 512 × 128 image
// spanning the bounds, and a point light above.
void make_rays(BenchScene& scene) {
    const Bounds3 box = scene.bvh->bounds();
    const Vec3 center = box.center();
    const double size = length(box.extent());
    const Vec3 eye = center + Vec3{0.3, 0.4, 1.0} * (1.1 * size);
    const Frame frame = Frame::from_normal(normalize(center - eye));
    const Vec3 light = center + Vec3{-0.5, 1.5, 0.5} * size;
    const int width = 512, height = static_cast<int>(kRaysPerSet / 512);
    make_rays(
        scene, width,
        [&](int x, int y) {
            const double sx = (x + 0.5) / width - 0.5, sy = (y + 0.5) / height - 0.5;
            return Ray{
                eye, normalize(frame.n +
                               0.55 * (sx * frame.s + sy * frame.t * (static_cast<double>(height) / width)))};
        },
        [&](double, double) { return light; });
}

// Book 2's Cornell box as examples/rtiow-cornell.yaml builds it, with its camera's rays through a
// 256 × 256 grid of its 400 × 400 image and shadow rays to uniform points of its light.
std::unique_ptr<BenchScene> cornell_scene() {
    auto scene = std::make_unique<BenchScene>();
    const Scene built = build_scene(load_scene_file(GLINT_SOURCE_DIR "/examples/rtiow-cornell.yaml"));
    scene->world = built.world;
    for (const auto& shape : built.world->shapes) {
        scene->pointers.push_back(shape.get());
    }
    scene->bvh = std::make_unique<BvhAccelerator>(scene->pointers);
#ifdef GLINT_HAVE_EMBREE
    scene->embree = std::make_unique<EmbreeAccelerator>(scene->pointers, embree_config);
#endif
    const auto* light = dynamic_cast<const AreaLight*>(built.world->lights.at(0).get());
    if (light == nullptr) {
        throw std::runtime_error("rtiow-cornell.yaml's first light is not an area light");
    }
    const int grid = 256;
    const double scale = static_cast<double>(built.view.settings.width) / grid;
    make_rays(
        *scene, grid,
        [&](int x, int y) {
            return built.view.camera->generate_ray({(x + 0.5) * scale, (y + 0.5) * scale}, {0.5, 0.5});
        },
        [&](double u, double v) {
            return light->shape().sample_area({u, v})->point;
        });
    return scene;
}

std::unique_ptr<BenchScene> finish(std::unique_ptr<BenchScene> scene, bool with_embree) {
    for (const auto& s : scene->shapes) {
        scene->pointers.push_back(s.get());
        if (const auto* mesh = dynamic_cast<const Mesh*>(s.get())) {
            scene->triangles += mesh->triangles().size();
        }
    }
    scene->bvh = std::make_unique<BvhAccelerator>(scene->pointers);
#ifdef GLINT_HAVE_EMBREE
    if (with_embree) {
        scene->embree = std::make_unique<EmbreeAccelerator>(scene->pointers, embree_config);
    }
#else
    (void)with_embree;
#endif
    make_rays(*scene);
    return scene;
}

const MeshData& large_mesh_data() {
    static const MeshData mesh = large_mesh().make();
    return mesh;
}

BenchScene& scene(const std::string& name) {
    static std::map<std::string, std::unique_ptr<BenchScene>> cache;
    auto& slot = cache[name];
    if (!slot) {
        auto s = std::make_unique<BenchScene>();
        bool with_embree = true;
        if (name == small_mesh().name) {
            s->shapes.push_back(std::make_unique<Mesh>(small_mesh().make()));
        } else if (name == large_mesh().name) {
            s->shapes.push_back(std::make_unique<Mesh>(large_mesh_data()));
        } else if (name == "spheres100k") {
            std::mt19937_64 rng(3);
            std::uniform_real_distribution<double> u(0, 1);
            for (int i = 0; i < 100000; ++i) {
                s->shapes.push_back(std::make_unique<Sphere>(Vec3{100 * u(rng), 100 * u(rng), 100 * u(rng)},
                                                             0.3 + 0.7 * u(rng)));
            }
        } else if (name == "cornell") {
            slot = cornell_scene();
            return *slot;
        } else if (name == "sphere1k") {
            s->shapes.push_back(std::make_unique<Mesh>(uv_sphere(32, 17)));  // 1 024 triangles
            with_embree = false;
        } else if (name == "sphere1M") {
            s->shapes.push_back(std::make_unique<Mesh>(uv_sphere(1024, 513)));  // 1 048 576 triangles
            with_embree = false;
        } else if (name == "sphere2k") {
            s->shapes.push_back(std::make_unique<Mesh>(tessellated_sphere(4)));  // 2 048 triangles
            with_embree = false;
        } else if (name == "sphere2M") {
            s->shapes.push_back(std::make_unique<Mesh>(tessellated_sphere(9)));  // 2 097 152 triangles
            with_embree = false;
        }
        slot = finish(std::move(s), with_embree);
    }
    return *slot;
}

// Traces every ray of `set` on the arena's threads; returns how many hit.
std::uint64_t trace_all(tbb::task_arena& arena, const Accelerator& accel, const RaySet& set) {
    std::atomic<std::uint64_t> found{0};
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, set.rays.size(), 1024), [&](const auto& range) {
            std::uint64_t local = 0;
            for (std::size_t i = range.begin(); i < range.end(); ++i) {
                if (set.shadow) {
                    local += accel.occluded(set.rays[i], 1.0) ? 1 : 0;
                } else {
                    Hit hit;
                    local += accel.intersect(set.rays[i], kInf, hit) ? 1 : 0;
                }
            }
            found += local;
        });
    });
    return found;
}

void BM_Rays(benchmark::State& state, const std::string& scene_name, const std::string& kind, bool embree) {
    BenchScene& s = scene(scene_name);
    const Accelerator* accel = embree ? s.embree.get() : s.bvh.get();
    if (accel == nullptr) {
        state.SkipWithError("Embree is not built in");
        return;
    }
    const RaySet& set = s.ray_sets.at(kind);
    tbb::task_arena arena(kThreads);
    std::uint64_t rays = 0, hits = 0;
    for (auto _ : state) {
        hits = trace_all(arena, *accel, set);
        rays += set.rays.size();
    }
    state.counters["Mrays/s"] =
        benchmark::Counter(static_cast<double>(rays) * 1e-6, benchmark::Counter::kIsRate);
    state.counters["hit%"] = 100.0 * static_cast<double>(hits) / static_cast<double>(set.rays.size());
    state.counters["tris"] = static_cast<double>(s.triangles);
}

// ---------------------------------------------------------------------------------------------------
// A render's own rays, replayed. bench-peers sets glint's whole-render rate against this kernel's
// (docs/benchmarks.md, "What is measured"). The ray sets above hold one kind of ray each, in pixel order:
// neighbouring rays take the same branches, one after another. A render asks for its rays as its paths
// make them: a pixel's camera rays, then each path's shadow ray and bounce in turn, from wherever the
// path has got to. `Rays/NAME/render/bvh` records the queries that a glint render of a scene file asks
// its accelerator, in the order it asks them (one thread), and replays them through that same
// accelerator on kThreads threads, each taking runs of consecutive queries: the kernel on exactly the
// render's rays, without the rest of the render.

// One query as the render asked it. A packet (intersect_packet) is its rays' queries in a row, the first
// of them giving their number.
struct Query {
    enum class Kind : std::uint8_t { nearest, any, packet };
    Ray ray;
    double t_max = 0;
    Kind kind = Kind::nearest;
    bool found = false;             // what the render's query found (the replay checks it finds the same)
    std::uint32_t packet_size = 1;  // a packet's first query: how many rays; the rest of it: 0
};
constexpr int kMaxPacket = 64;

// Passes every query to `traced` and appends it to `log`. Not thread-safe: the recorded render has one
// thread.
class RecordingAccelerator final : public Accelerator {
  public:
    RecordingAccelerator(std::shared_ptr<const Accelerator> traced, std::vector<Query>& log)
        : traced_(std::move(traced)), log_(&log) {}
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override {
        const bool found = traced_->intersect(ray, t_max, hit);
        log_->push_back({ray, t_max, Query::Kind::nearest, found, 1});
        return found;
    }
    void intersect_packet(const Ray* const* rays, int n, double t_max, Hit* const* hits,
                          bool* found) const override {
        if (n > kMaxPacket) {
            throw std::runtime_error("a packet of more than kMaxPacket rays: raise kMaxPacket");
        }
        traced_->intersect_packet(rays, n, t_max, hits, found);
        for (int k = 0; k < n; ++k) {
            log_->push_back(
                {*rays[k], t_max, Query::Kind::packet, found[k], k == 0 ? static_cast<std::uint32_t>(n) : 0});
        }
    }
    bool traces_packets() const override { return traced_->traces_packets(); }
    bool occluded(const Ray& ray, double t_max) const override {
        const bool found = traced_->occluded(ray, t_max);
        log_->push_back({ray, t_max, Query::Kind::any, found, 1});
        return found;
    }
    Bounds3 bounds() const override { return traced_->bounds(); }

  private:
    std::shared_ptr<const Accelerator> traced_;
    std::vector<Query>* log_;
};

struct RecordedRender {
    // The shapes the accelerator points to, kept alive. Not the world: its accelerator is the recorder,
    // whose log this struct no longer is once returned.
    std::vector<std::shared_ptr<const Shape>> shapes;
    std::shared_ptr<const Accelerator> accelerator;  // the world's own, which the render traced
    std::vector<Query> queries;
    std::vector<std::size_t> runs;  // where each run of queries that one thread replays in order begins
};

// --render-scene=NAME=FILE (Rays/NAME/render/bvh; the Cornell box's is built in) and --render-spp=N.
std::map<std::string, std::string> render_scene_files = {
    {"cornell", GLINT_SOURCE_DIR "/examples/rtiow-cornell.yaml"}};
std::uint32_t render_spp = 16;

// Renders `file` at its own size and settings but render_spp samples a pixel (16: the render loop's
// passes of 16, each pixel's paths together, as in a render of 64), recording what its world's
// accelerator is asked (64 bytes a query, held until the replayed set is taken from them). The cache
// hands the second build the accelerator of the first, wrapped.
RecordedRender record_render(const std::string& file) {
    SceneDesc desc = load_scene_file(file);
    RenderFlags flags;
    flags.samples_per_pixel = render_spp;
    apply_flags(desc, flags);
    WorldCache cache;
    build_scene(desc, &cache);
    RecordedRender recorded;
    recorded.accelerator = cache.accelerator.accelerator;
    const auto recorder = std::make_shared<RecordingAccelerator>(recorded.accelerator, recorded.queries);
    cache.accelerator.accelerator = recorder;
    Scene scene = build_scene(desc, &cache);
    if (scene.world->accelerator != recorder) {
        throw std::runtime_error(file + ": the second build did not take the cached accelerator");
    }
    recorded.shapes = scene.world->shapes;
    scene.view.settings.threads = 1;
    Film film(scene.view.settings.width, scene.view.settings.height);
    const RenderStats stats = render(*scene.world, scene.view, film);
    if (recorded.queries.size() != stats.rays.total()) {
        throw std::runtime_error(file + ": recorded " + std::to_string(recorded.queries.size()) +
                                 " queries, the render counted " + std::to_string(stats.rays.total()));
    }
    // The replayed set: kRuns runs of kRunLength consecutive queries (a packet is not cut), spread evenly
    // over the render, 65 536 queries in all like the sets above, so that they stay in the caches as
    // those do. Replayed from memory, a log as large as the Cornell box's at 16 spp (16 M queries, 1 GB)
    // slows the kernel by itself, a cost no render has, as it makes each ray where it traces it: the
    // Cornell box's own sets, each replayed 100 times over from such a log, ran at 0.83 (primary), 0.99
    // (diffuse) and 0.57 (shadow) of their rates, and at 1.00 from a log of one copy.
    constexpr std::size_t kRuns = 64, kRunLength = 1024;
    std::vector<Query> all = std::move(recorded.queries);
    recorded.queries.clear();
    for (std::size_t r = 0; r < kRuns; ++r) {
        std::size_t i = r * all.size() / kRuns;
        while (i < all.size() && all[i].packet_size == 0) {
            ++i;
        }
        const std::size_t begin = i;
        while (i < all.size() && (i - begin < kRunLength || all[i].packet_size == 0)) {
            ++i;
        }
        if (i > begin) {
            recorded.runs.push_back(recorded.queries.size());
            recorded.queries.insert(recorded.queries.end(), all.begin() + static_cast<std::ptrdiff_t>(begin),
                                    all.begin() + static_cast<std::ptrdiff_t>(i));
        }
    }
    return recorded;
}

const RecordedRender& recorded_render(const std::string& name) {
    static std::map<std::string, RecordedRender> cache;
    auto it = cache.find(name);
    if (it == cache.end()) {
        it = cache.emplace(name, record_render(render_scene_files.at(name))).first;
    }
    return it->second;
}

// Asks `accel` each of `queries` in order; returns how many found other than the render's query did.
std::uint64_t replay(const Accelerator& accel, std::span<const Query> queries) {
    std::uint64_t differ = 0;
    for (std::size_t i = 0; i < queries.size();) {
        const Query& q = queries[i];
        if (q.kind == Query::Kind::any) {
            differ += accel.occluded(q.ray, q.t_max) != q.found ? 1 : 0;
            ++i;
        } else if (q.kind == Query::Kind::nearest) {
            Hit hit;
            differ += accel.intersect(q.ray, q.t_max, hit) != q.found ? 1 : 0;
            ++i;
        } else {
            const int n = static_cast<int>(q.packet_size);
            const Ray* rays[kMaxPacket];
            Hit records[kMaxPacket];
            Hit* hits[kMaxPacket];
            bool hit_found[kMaxPacket];
            for (int k = 0; k < n; ++k) {
                rays[k] = &queries[i + static_cast<std::size_t>(k)].ray;
                hits[k] = &records[k];
            }
            accel.intersect_packet(rays, n, q.t_max, hits, hit_found);
            for (int k = 0; k < n; ++k) {
                differ += hit_found[k] != queries[i + static_cast<std::size_t>(k)].found ? 1 : 0;
            }
            i += static_cast<std::size_t>(n);
        }
    }
    return differ;
}

void BM_RenderRays(benchmark::State& state, const std::string& name) {
    const RecordedRender& recorded = recorded_render(name);
    const std::vector<Query>& queries = recorded.queries;
    tbb::task_arena arena(kThreads);
    std::uint64_t rays = 0, differ = 0;
    for (auto _ : state) {
        std::atomic<std::uint64_t> differ_now{0};
        arena.execute([&] {
            tbb::parallel_for(
                tbb::blocked_range<std::size_t>(0, recorded.runs.size(), 1), [&](const auto& range) {
                    for (std::size_t r = range.begin(); r < range.end(); ++r) {
                        const std::size_t begin = recorded.runs[r];
                        const std::size_t end =
                            r + 1 < recorded.runs.size() ? recorded.runs[r + 1] : queries.size();
                        differ_now +=
                            replay(*recorded.accelerator, std::span(queries).subspan(begin, end - begin));
                    }
                });
        });
        differ += differ_now;
        rays += queries.size();
    }
    if (differ != 0) {
        state.SkipWithError("a replayed query found other than the render's did");
        return;
    }
    std::uint64_t shadow = 0, found = 0;
    for (const Query& q : queries) {
        shadow += q.kind == Query::Kind::any ? 1 : 0;
        found += q.found ? 1 : 0;
    }
    state.counters["Mrays/s"] =
        benchmark::Counter(static_cast<double>(rays) * 1e-6, benchmark::Counter::kIsRate);
    state.counters["hit%"] = 100.0 * static_cast<double>(found) / static_cast<double>(queries.size());
    state.counters["shadow%"] = 100.0 * static_cast<double>(shadow) / static_cast<double>(queries.size());
}

void BM_BuildLargeMesh(benchmark::State& state) {
    const MeshData& data = large_mesh_data();
    double bytes_per_triangle = 0;
    for (auto _ : state) {
        // Timed: what a render does with a loaded mesh (moves it into a Mesh, which builds). Not timed:
        // copying the input, and freeing the built mesh.
        state.PauseTiming();
        MeshData input = data;
        std::optional<Mesh> mesh;
        state.ResumeTiming();
        mesh.emplace(std::move(input));
        benchmark::DoNotOptimize(mesh->bvh().nodes().data());
        state.PauseTiming();
        bytes_per_triangle =
            static_cast<double>(mesh->memory_bytes()) / static_cast<double>(mesh->triangles().size());
        mesh.reset();
        state.ResumeTiming();
    }
    state.counters["Mtris/s"] = benchmark::Counter(
        static_cast<double>(data.triangles.size()) * 1e-6 * static_cast<double>(state.iterations()),
        benchmark::Counter::kIsRate);
    state.counters["bytes/tri"] = bytes_per_triangle;
}

// The scenes that glint's BVH and Embree race on, each with every kind of ray (kRayKinds): the
// ordinary runs register them, --pairs walks them.
std::vector<std::string> raced_scenes() {
    return {small_mesh().name, large_mesh().name, "spheres100k", "cornell"};
}
constexpr const char* kRayKinds[] = {"primary", "diffuse", "shadow"};

void register_all() {
    for (const std::string& name : raced_scenes()) {
        for (const char* kind : kRayKinds) {
            for (bool embree : {false, true}) {
                const std::string label =
                    std::string("Rays/") + name + "/" + kind + "/" + (embree ? "embree" : "bvh");
                benchmark::RegisterBenchmark(label.c_str(), BM_Rays, name, std::string(kind), embree)
                    ->UseRealTime()
                    ->Unit(benchmark::kMillisecond);
            }
        }
    }
    for (const char* name : {"sphere1k", "sphere1M", "sphere2k", "sphere2M"}) {
        benchmark::RegisterBenchmark((std::string("Rays/") + name + "/primary/bvh").c_str(), BM_Rays,
                                     std::string(name), std::string("primary"), false)
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
    }
    for (const auto& [name, file] : render_scene_files) {
        benchmark::RegisterBenchmark(("Rays/" + name + "/render/bvh").c_str(), BM_RenderRays, name)
            ->UseRealTime()
            ->Unit(benchmark::kMillisecond);
    }
    benchmark::RegisterBenchmark(("Build/" + large_mesh().name).c_str(), BM_BuildLargeMesh)
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
}

// Prints the runs as usual and remembers each benchmark's Mrays/s, for the ratios at the end: the
// median when the runs are repeated (--benchmark_repetitions=N), else the one run.
class RatioReporter : public benchmark::ConsoleReporter {
  public:
    void ReportRuns(const std::vector<Run>& runs) override {
        ConsoleReporter::ReportRuns(runs);
        for (const Run& run : runs) {
            if (run.run_type == Run::RT_Aggregate && run.aggregate_name != "median") {
                continue;
            }
            const auto it = run.counters.find("Mrays/s");
            if (it != run.counters.end()) {
                rates[run.run_name.function_name] = it->second.value;  // e.g. Rays/bunny/shadow/bvh
            }
        }
    }
    std::map<std::string, double> rates;
};

// The 95 % interval of the median of n values, as indices into them sorted: order statistics k and
// n − 1 − k, with k the largest for which 1 − 2 P(X ≤ k) ≥ 0.95, X ~ Binomial(n, ½) being how many of
// the values fall below the true median (the interval misses it when k or fewer fall below it, or k or
// fewer above). Holds whatever the values' distribution; needs n ≥ 6.
std::pair<std::size_t, std::size_t> median_interval(std::size_t n) {
    // P(X ≤ k) for X ~ Binomial(n, ½), summed term by term (n is small).
    auto below = [n](std::size_t k) {
        double term = std::ldexp(1.0, -static_cast<int>(n));  // P(X = 0)
        double sum = term;
        for (std::size_t i = 1; i <= k; ++i) {
            term *= static_cast<double>(n - i + 1) / static_cast<double>(i);
            sum += term;
        }
        return sum;
    };
    std::size_t k = 0;
    while (k + 1 < n / 2 && 2 * below(k + 1) <= 0.05) {
        ++k;
    }
    return {k, n - 1 - k};
}

// --pairs=N: glint's BVH and Embree on each selected ray set, N rounds of the two back to back
// (alternating which goes first), and the median of the rounds' rays/s ratios with its interval.
int run_pairs(int rounds, const std::string& filter) {
    if (rounds < 6 || rounds > 1000) {
        std::fprintf(stderr, "--pairs: from 6 rounds (for a 95 %% interval of the median) to 1000\n");
        return 2;
    }
    std::regex selected;
    try {
        selected = std::regex(filter.empty() || filter == "all" ? "." : filter);
    } catch (const std::regex_error& e) {
        std::fprintf(stderr, "--benchmark_filter: '%s' is not a regular expression (%s)\n", filter.c_str(),
                     e.what());
        return 2;
    }
    tbb::task_arena arena(kThreads);
    const auto [low, high] = median_interval(static_cast<std::size_t>(rounds));
    std::printf(
        "bvh / embree, rays/s ratio (%d threads), %d rounds of the two back to back: median "
        "[95 %% interval]%s%s\n",
        kThreads, rounds, embree_config.empty() ? "" : "; Embree's device: ", embree_config.c_str());
    for (const std::string& name : raced_scenes()) {
        for (const char* kind : kRayKinds) {
            const std::string label = "Rays/" + name + "/" + kind;
            // Either of the pair's names as Google Benchmark's runs have them.
            if (!std::regex_search(label + "/bvh/real_time", selected) &&
                !std::regex_search(label + "/embree/real_time", selected)) {
                continue;
            }
            BenchScene& s = scene(name);
            if (!s.embree) {
                std::printf("  %-28s Embree is not built in\n", label.c_str());
                continue;
            }
            const RaySet& set = s.ray_sets.at(kind);
            auto seconds = [&](const Accelerator& accel) {
                const auto start = std::chrono::steady_clock::now();
                benchmark::DoNotOptimize(trace_all(arena, accel, set));
                return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            };
            seconds(*s.bvh);  // warm: caches, and the threads started
            seconds(*s.embree);
            std::vector<double> ratios;
            for (int r = 0; r < rounds; ++r) {
                double bvh = 0, embree = 0;
                if (r % 2 == 0) {
                    bvh = seconds(*s.bvh);
                    embree = seconds(*s.embree);
                } else {
                    embree = seconds(*s.embree);
                    bvh = seconds(*s.bvh);
                }
                ratios.push_back(embree / bvh);  // rays/s of the BVH over Embree's
            }
            std::sort(ratios.begin(), ratios.end());
            const double median = rounds % 2 == 1
                                      ? ratios[ratios.size() / 2]
                                      : (ratios[ratios.size() / 2 - 1] + ratios[ratios.size() / 2]) / 2;
            std::printf("  %-28s %.2f [%.2f, %.2f]\n", label.c_str(), median, ratios[low], ratios[high]);
        }
    }
    return 0;
}

// How many times slower a ray is in the larger scene.
void print_growth(const std::map<std::string, double>& rates, const std::string& small,
                  const std::string& large, const char* label) {
    const auto s = rates.find("Rays/" + small + "/primary/bvh");
    const auto l = rates.find("Rays/" + large + "/primary/bvh");
    if (s != rates.end() && l != rates.end() && l->second > 0) {
        std::printf("cost per ray, %s: %.2fx (target <= 3x)\n", label, s->second / l->second);
    }
}

}  // namespace

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    int pairs = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg.starts_with("--pairs=")) {
            const char* end = arg.data() + arg.size();
            if (std::from_chars(arg.data() + 8, end, pairs).ptr != end || pairs == 0) {
                std::fprintf(stderr, "--pairs: expected a number of rounds, not '%s'\n", arg.c_str() + 8);
                return 2;
            }
        } else if (arg.starts_with("--embree-config=")) {
            embree_config = arg.substr(16);
        } else if (arg.starts_with("--render-scene=") && arg.find('=', 15) != std::string::npos) {
            const std::size_t equals = arg.find('=', 15);
            render_scene_files[arg.substr(15, equals - 15)] = arg.substr(equals + 1);
        } else if (arg.starts_with("--render-spp=")) {
            const char* end = arg.data() + arg.size();
            if (std::from_chars(arg.data() + 13, end, render_spp).ptr != end || render_spp == 0) {
                std::fprintf(stderr, "--render-spp: expected a positive number, not '%s'\n",
                             arg.c_str() + 13);
                return 2;
            }
        } else {
            std::fprintf(stderr,
                         "unknown argument '%s' (expected --pairs=N, --embree-config=STRING, "
                         "--render-scene=NAME=FILE, "
                         "--render-spp=N or "
                         "Google Benchmark's --benchmark_* flags)\n",
                         argv[i]);
            return 2;
        }
    }
    for (const MeshSource* source : {&small_mesh(), &large_mesh()}) {
        if (!source->note.empty()) {
            std::printf("%s\n", source->note.c_str());
        }
    }
    if (pairs != 0) {
        return run_pairs(pairs, benchmark::GetBenchmarkFilter());
    }
    register_all();
    RatioReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    std::printf("\nbvh / embree (rays/s ratio, %d threads; target >= 0.9 on meshes, >= 1.0 on spheres):\n",
                kThreads);
    for (const auto& [name, rate] : reporter.rates) {
        const std::string suffix = "/bvh";
        if (!name.ends_with(suffix)) {
            continue;
        }
        const std::string base = name.substr(0, name.size() - suffix.size());
        const auto other = reporter.rates.find(base + "/embree");
        if (other != reporter.rates.end() && other->second > 0) {
            std::printf("  %-28s %.2f\n", base.c_str(), rate / other->second);
        }
    }
    print_growth(reporter.rates, "sphere1k", "sphere1M", "1 M vs 1 k triangles (UV spheres)");
    print_growth(reporter.rates, "sphere2k", "sphere2M", "2 M vs 2 k triangles (subdivided octahedra)");
    benchmark::Shutdown();
    return 0;
}
