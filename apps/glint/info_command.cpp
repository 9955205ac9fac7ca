// `glint info SCENE`: counts of primitives and triangles, the scene's bounds, and the BVH's build time,
// node count and memory — what to look at before a long render of a big scene.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.hpp"
#include "glint/accel/bvh.hpp"
#include "glint/geometry/instance.hpp"
#include "glint/geometry/mesh.hpp"
#include "glint/import/importer.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"

namespace {

constexpr int kExitBadInput = 2;

std::string megabytes(std::size_t bytes) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.2f MB", static_cast<double>(bytes) / (1024.0 * 1024.0));
    return text;
}

int run_info(const std::string& scene_path) {
    glint::Scene scene;
    try {
        const glint::SceneDesc desc = glint::load_scene(scene_path);
        print_warnings(desc);
        scene = glint::build_scene(desc);
    } catch (const glint::SceneError& e) {
        std::cerr << e.what() << '\n';
        return kExitBadInput;
    }
    std::size_t meshes = 0, triangles = 0, vertices = 0, mesh_nodes = 0, mesh_bytes = 0;
    double mesh_build_seconds = 0;
    for (const auto& shape : scene.world->shapes) {
        // A mesh placed by a `transform` is a mesh inside an instance: it counts the same.
        const glint::Shape* placed = shape.get();
        while (const auto* instance = dynamic_cast<const glint::Instance*>(placed)) {
            placed = &instance->shape();
        }
        if (const auto* mesh = dynamic_cast<const glint::Mesh*>(placed)) {
            ++meshes;
            triangles += mesh->triangles().size();
            vertices += mesh->positions().size();
            mesh_nodes += mesh->bvh().nodes().size();
            mesh_bytes += mesh->memory_bytes();
            mesh_build_seconds += mesh->build_seconds();
        }
    }
    // The scene's own BVH over its shapes, built again here so that its figures do not depend on the
    // accelerator the scene file chose.
    std::vector<const glint::Shape*> shapes;
    for (const auto& s : scene.world->shapes) {
        shapes.push_back(s.get());
    }
    const glint::BvhAccelerator top(shapes);
    const glint::Bounds3 bounds = top.bounded_bounds();  // planes would make the scene's bounds infinite

    std::printf("scene        %s\n", scene_path.c_str());
    std::printf("primitives   %zu (%zu meshes, %zu other shapes, %zu unbounded kept outside the BVH)\n",
                scene.world->shapes.size(), meshes, scene.world->shapes.size() - meshes,
                top.unbounded_count());
    std::printf("triangles    %zu (%zu vertices)\n", triangles, vertices);
    std::printf("bounds       %s[%g, %g, %g] .. [%g, %g, %g]\n",
                top.unbounded_count() > 0 ? "(bounded shapes) " : "", bounds.lo.x, bounds.lo.y, bounds.lo.z,
                bounds.hi.x, bounds.hi.y, bounds.hi.z);
    std::printf("accelerator  %s (render default; --accel on `glint render` overrides)\n",
                scene.view.settings.accelerator.c_str());
    const double build_seconds = mesh_build_seconds + top.build_seconds();
    std::printf("bvh build    %.3f s (meshes %.3f s, scene level %.3f s)\n", build_seconds,
                mesh_build_seconds, top.build_seconds());
    if (triangles > 0 && mesh_build_seconds > 0) {
        std::printf("build rate   %.2f M triangles/s\n",
                    static_cast<double>(triangles) / mesh_build_seconds * 1e-6);
    }
    std::printf("bvh nodes    %zu (8-wide; %zu in meshes, %zu at scene level)\n",
                mesh_nodes + top.bvh().nodes().size(), mesh_nodes, top.bvh().nodes().size());
    std::printf("memory       %s (meshes with their BVHs %s, scene-level BVH %s)\n",
                megabytes(mesh_bytes + top.bvh().memory_bytes()).c_str(), megabytes(mesh_bytes).c_str(),
                megabytes(top.bvh().memory_bytes()).c_str());
    if (triangles > 0) {
        std::printf("per triangle %.1f bytes (vertices, normals, indices, BVH)\n",
                    static_cast<double>(mesh_bytes) / static_cast<double>(triangles));
    }
    std::printf("traversal    %s\n", glint::WideBvh::uses_avx2() ? "AVX2" : "scalar (no AVX2 on this CPU)");
    return 0;
}

}  // namespace

void add_info_command(CLI::App& app) {
    auto scene_path = std::make_shared<std::string>();
    CLI::App* info = app.add_subcommand("info",
                                        "Describe a scene: primitives, triangles, bounds, BVH build time, "
                                        "node count and memory");
    info->add_option("scene", *scene_path, "Scene file (YAML or JSON)")->required();
    info->callback([scene_path] {
        if (const int code = run_info(*scene_path); code != 0) {
            throw CLI::RuntimeError(code);
        }
    });
}
