#include "glint/accel/bvh.hpp"

#include <chrono>
#include <limits>

#include "glint/geometry/sphere.hpp"

namespace glint {

BvhAccelerator::BvhAccelerator(std::span<const Shape* const> shapes) : all_(shapes.begin(), shapes.end()) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<Bounds3> boxes;
    std::vector<std::uint32_t> bounded;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const Bounds3 b = shapes[i]->bounds();
        bounds_.grow(b);
        // The tree stores boxes in float: a box beyond float's range (a sphere of radius 1e116) would
        // saturate to infinity there, and a box infinite in every direction broke the traversal. Such
        // shapes are tested apart, as unbounded ones are.
        const double float_max = std::numeric_limits<float>::max();
        const bool fits_float =
            b.is_finite() && max_component(abs(b.lo)) <= float_max && max_component(abs(b.hi)) <= float_max;
        if (fits_float) {
            bounded_bounds_.grow(b);
            boxes.push_back(b);
            bounded.push_back(static_cast<std::uint32_t>(i));
        } else if (!b.empty()) {
            direct_.push_back(static_cast<std::uint32_t>(i));
        }
    }
    unbounded_count_ = direct_.size();
    if (boxes.size() == 1) {
        direct_.push_back(bounded[0]);
        boxes.clear();
        bounded.clear();
    }
    bvh_.build(boxes);
    for (std::uint32_t position : bvh_.primitive_order()) {
        const Shape* shape = shapes[bounded[position]];
        shapes_.push_back(shape);
        shape_index_.push_back(bounded[position]);
        const auto* sphere = dynamic_cast<const Sphere*>(shape);
        leaf_spheres_.push_back(sphere != nullptr ? LeafSphere{sphere->center(), sphere->radius()}
                                                  : LeafSphere{});
    }
    build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool BvhAccelerator::intersect(const Ray& ray, double t_max, Hit& hit) const {
    bool found = false;
    for (std::uint32_t i : direct_) {
        if (all_[i]->intersect(ray, t_max, hit)) {
            t_max = hit.t;
            hit.primitive = i;
            found = true;
        }
    }
    // The nearest sphere so far, if it is nearer than every other hit: its Hit is filled at the end.
    constexpr std::uint32_t kNone = ~0u;
    std::uint32_t nearest_sphere = kNone;
    const double t_max_given = t_max;
    found |= bvh_.intersect(ray, t_max, [&](std::uint32_t first, std::uint32_t count, double& t_limit, auto) {
        bool any = false;
        for (std::uint32_t i = first; i < first + count; ++i) {
            const LeafSphere& sphere = leaf_spheres_[i];
            if (sphere.radius > 0) {
                double t = 0;
                if (sphere_hit_t(sphere.center, sphere.radius, ray, t_limit, t)) {
                    t_limit = t;
                    nearest_sphere = i;
                    any = true;
                }
            } else if (shapes_[i]->intersect(ray, t_limit, hit)) {
                t_limit = hit.t;
                hit.primitive = shape_index_[i];
                nearest_sphere = kNone;
                any = true;
            }
        }
        return any;
    });
    if (nearest_sphere != kNone) {
        // The same computation finds the same t, now with the normal and uv.
        if (!shapes_[nearest_sphere]->intersect(ray, t_max_given, hit)) {
            return false;  // cannot happen
        }
        hit.primitive = shape_index_[nearest_sphere];
    }
    return found;
}

bool BvhAccelerator::occluded(const Ray& ray, double t_max) const {
    for (std::uint32_t i : direct_) {
        if (all_[i]->occluded(ray, t_max)) {
            return true;
        }
    }
    return bvh_.occluded(
        ray, t_max, [&](std::uint32_t first, std::uint32_t count, double t_limit, auto /*avx2*/) {
            for (std::uint32_t i = first; i < first + count; ++i) {
                const LeafSphere& sphere = leaf_spheres_[i];
                if (sphere.radius > 0 ? sphere_occludes(sphere.center, sphere.radius, ray, t_limit)
                                      : shapes_[i]->occluded(ray, t_limit)) {
                    return true;
                }
            }
            return false;
        });
}

}  // namespace glint
