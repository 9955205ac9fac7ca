// Scenes and rays shared by the accelerator tests: random spheres, closed tessellated meshes, the bunny.
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "generated_meshes.hpp"
#include "glint/accel/accelerator.hpp"
#include "glint/core/math.hpp"
#include "glint/geometry/mesh.hpp"
#include "glint/geometry/sphere.hpp"

namespace glint::test {

inline Vec3 random_in_box(std::mt19937_64& rng, const Vec3& lo, const Vec3& hi) {
    std::uniform_real_distribution<double> u(0, 1);
    return {lo.x + u(rng) * (hi.x - lo.x), lo.y + u(rng) * (hi.y - lo.y), lo.z + u(rng) * (hi.z - lo.z)};
}

inline Vec3 random_direction(std::mt19937_64& rng) {
    std::normal_distribution<double> g(0, 1);
    while (true) {
        const Vec3 d{g(rng), g(rng), g(rng)};
        if (length_squared(d) > 1e-6) {
            return normalize(d);
        }
    }
}

inline std::vector<std::unique_ptr<Shape>> random_spheres(int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> radius(0.05, 0.6);
    std::vector<std::unique_ptr<Shape>> shapes;
    for (int i = 0; i < count; ++i) {
        shapes.push_back(
            std::make_unique<Sphere>(random_in_box(rng, {-10, -10, -10}, {10, 10, 10}), radius(rng)));
    }
    return shapes;
}

// Splits each triangle of a mesh on the unit sphere into four, `subdivisions` times, putting each new
// vertex (an edge's midpoint, shared by the edge's two triangles) back on the sphere.
inline void subdivide_on_unit_sphere(MeshData& mesh, int subdivisions) {
    for (int s = 0; s < subdivisions; ++s) {
        std::vector<std::array<std::uint32_t, 3>> finer;
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
        auto mid = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = std::minmax(a, b);
            const auto [it, inserted] =
                midpoint.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
            if (inserted) {
                mesh.positions.push_back(normalize(mesh.positions[a] + mesh.positions[b]));
            }
            return it->second;
        };
        for (const auto& t : mesh.triangles) {
            const std::uint32_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
            finer.push_back({t[0], ab, ca});
            finer.push_back({ab, t[1], bc});
            finer.push_back({ca, bc, t[2]});
            finer.push_back({ab, bc, ca});
        }
        mesh.triangles = std::move(finer);
    }
}

// A closed sphere of triangles: a subdivided octahedron projected on the unit sphere, vertices shared.
inline MeshData tessellated_sphere(int subdivisions, double radius = 1, const Vec3& center = {}) {
    MeshData mesh;
    mesh.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    mesh.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    subdivide_on_unit_sphere(mesh, subdivisions);
    for (Vec3& p : mesh.positions) {
        p = center + radius * p;
    }
    return mesh;
}

// A mesh with the properties of the Stanford bunny that matter to a BVH, made by code so that every
// clone can test with it: 81 920 triangles (the bunny has 69 451) sharing 40 962 vertices, closed, not
// convex (a subdivided icosahedron whose radius is displaced by three sine waves: bumps and hollows that
// shadow each other), bunny-sized (about 0.16 across) and off the origin. Every vertex moves along its
// own direction from the centre, by a radius between 0.62 and 1.38, so the surface stays closed and
// never meets itself.
inline MeshData displaced_blob(int subdivisions = 6) {
    MeshData mesh;
    const double g = (1 + std::sqrt(5.0)) / 2;  // the icosahedron's vertices: (0, ±1, ±g) cycled
    mesh.positions = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                      {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    for (Vec3& p : mesh.positions) {
        p = normalize(p);
    }
    mesh.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    subdivide_on_unit_sphere(mesh, subdivisions);
    const Vec3 scale{0.08, 0.068, 0.056};
    const Vec3 offset{-0.017, 0.11, -0.002};
    for (Vec3& p : mesh.positions) {
        const double r = 1 + 0.20 * std::sin(5 * p.x + 1) * std::sin(4 * p.y) +
                         0.12 * std::sin(9 * p.z + 2 * p.x) + 0.06 * std::sin(15 * p.y + 7 * p.z + 0.5);
        p = offset + Vec3{scale.x * r * p.x, scale.y * r * p.y, scale.z * r * p.z};
    }
    return mesh;
}

// A closed axis-aligned cube [lo, hi]³ of 12 triangles, outward winding.
inline MeshData cube_mesh(double lo, double hi) {
    MeshData mesh;
    for (int i = 0; i < 8; ++i) {
        mesh.positions.push_back({(i & 1) ? hi : lo, (i & 2) ? hi : lo, (i & 4) ? hi : lo});
    }
    const std::uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : quads) {
        mesh.triangles.push_back({q[0], q[1], q[2]});
        mesh.triangles.push_back({q[0], q[2], q[3]});
    }
    return mesh;
}

inline std::vector<const Shape*> pointers(const std::vector<std::unique_ptr<Shape>>& shapes) {
    std::vector<const Shape*> out;
    for (const auto& s : shapes) {
        out.push_back(s.get());
    }
    return out;
}

// Rays from random points around `box`, aimed at random points inside it (so most of them hit).
inline std::vector<Ray> rays_into(const Bounds3& box, int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    const Vec3 margin = box.extent();
    std::vector<Ray> rays;
    for (int i = 0; i < count; ++i) {
        const Vec3 origin = random_in_box(rng, box.lo - margin, box.hi + margin);
        const Vec3 target = random_in_box(rng, box.lo, box.hi);
        rays.push_back({origin, target - origin});
    }
    return rays;
}

// Rays that start on a surface, as a renderer's shadow and bounce rays do: from the hits of rays_into's
// rays, a shadow ray to each of two lights (to be asked with t_max = 1, the light) and a bounce ray in
// a random direction on the side the ray came from. `intersect(ray, hit)` finds the first hits.
struct SurfaceRays {
    std::vector<Ray> shadow, bounce;
};
template <class Intersect>
SurfaceRays surface_rays(const Bounds3& box, int count, std::uint64_t seed, Intersect&& intersect) {
    const double size = length(box.extent());
    const Vec3 lights[] = {box.center() + Vec3{-0.5, 1.5, 0.5} * size,
                           box.center() + Vec3{0.3, -0.2, 0.1} * size};
    std::mt19937_64 rng(seed);
    SurfaceRays out;
    for (const Ray& ray : rays_into(box, count, seed)) {
        Hit hit;
        if (!intersect(ray, hit)) {
            continue;
        }
        for (const Vec3& light : lights) {
            out.shadow.push_back(spawn_ray_to(hit, light));
        }
        Vec3 direction = random_direction(rng);
        if (dot(direction, hit.normal) * dot(ray.direction, hit.normal) > 0) {
            direction = -direction;
        }
        out.bounce.push_back(spawn_ray(hit, direction));
    }
    return out;
}

// Every field of two hit records, bit for bit: the same primitive's intersect must have filled both.
inline void expect_identical_hits(const Hit& a, const Hit& b, bool mesh) {
    const auto same_bits = [](const Vec3& x, const Vec3& y) {
        return x.x == y.x && x.y == y.y && x.z == y.z;
    };
    EXPECT_EQ(a.primitive, b.primitive);
    EXPECT_EQ(a.t, b.t);
    EXPECT_TRUE(same_bits(a.point, b.point));
    EXPECT_TRUE(same_bits(a.normal, b.normal));
    EXPECT_TRUE(same_bits(a.shading_normal, b.shading_normal));
    EXPECT_EQ(surface_uv(a).x, surface_uv(b).x);
    EXPECT_EQ(surface_uv(a).y, surface_uv(b).y);
    EXPECT_EQ(a.error, b.error);
    if (mesh) {
        EXPECT_EQ(a.element, b.element);  // other shapes leave `element` as it was
    }
}

// Compares two accelerators on `rays`: same hit or miss, same primitive and element, same t.
// hit.element is compared only where it means something: on meshes.
// Embree's leeway, for a backend that chooses triangles in float: a different triangle of the same
// mesh is accepted at the same t (triangles sharing an edge), and a shadow ray must be occluded only
// when it reaches a little further past the hit.
struct Leeway {
    bool tied_elements_allowed = false;
    double occlusion_margin = 1e-9;  // relative
};
inline void expect_same_hits(const Accelerator& reference, const Accelerator& tested,
                             const std::vector<Ray>& rays, const std::vector<const Shape*>& shapes,
                             Leeway leeway = {}) {
    int hits = 0;
    for (const Ray& ray : rays) {
        Hit a, b;
        const bool found_a = reference.intersect(ray, kInf, a);
        const bool found_b = tested.intersect(ray, kInf, b);
        ASSERT_EQ(found_a, found_b) << "ray " << ray.origin << " + t " << ray.direction;
        EXPECT_EQ(reference.occluded(ray, kInf), found_a);
        EXPECT_EQ(tested.occluded(ray, kInf), found_b);
        if (found_a) {
            ++hits;
            EXPECT_EQ(a.primitive, b.primitive);
            if (dynamic_cast<const Mesh*>(shapes[a.primitive]) != nullptr) {
                if (!leeway.tied_elements_allowed || std::abs(a.t - b.t) > 1e-9 * a.t) {
                    EXPECT_EQ(a.element, b.element);
                }
            }
            EXPECT_NEAR(a.t, b.t, 1e-12 * a.t);
            // A shadow ray stopping just short of the hit is not occluded by it, just past it is.
            EXPECT_EQ(tested.occluded(ray, a.t * (1 + leeway.occlusion_margin)), true);
        }
    }
    EXPECT_GT(hits, static_cast<int>(rays.size()) / 10);  // the test means something only if rays hit
}

}  // namespace glint::test
