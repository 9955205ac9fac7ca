#include "glint/accel/bvh.hpp"

#include <chrono>
#include <limits>

#include "glint/geometry/sphere.hpp"

namespace glint {

void BvhAccelerator::ShapeList::add(const Shape* shape, std::uint32_t index) {
    const auto* sphere = dynamic_cast<const Sphere*>(shape);
    spheres.push_back(sphere != nullptr ? LeafSphere{sphere->center(), sphere->radius()} : LeafSphere{});
    shapes.push_back(shape);
    scene_index.push_back(index);
}

BvhAccelerator::BvhAccelerator(std::span<const Shape* const> shapes, std::size_t flat_max_shapes) {
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
            direct_.add(shapes[i], static_cast<std::uint32_t>(i));
        }
    }
    unbounded_count_ = direct_.size();
    // A lone bounded shape (a scene of one mesh) is never worth a tree of one leaf.
    if (boxes.size() <= std::max<std::size_t>(flat_max_shapes, 1)) {
        for (std::uint32_t i : bounded) {
            direct_.add(shapes[i], i);
        }
        boxes.clear();
        bounded.clear();
    }
    bvh_.build(boxes);
    for (std::uint32_t position : bvh_.primitive_order()) {
        leaves_.add(shapes[bounded[position]], bounded[position]);
    }
    build_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool BvhAccelerator::intersect(const Ray& ray, double t_max, Hit& hit) const {
    // The nearest sphere so far (entry `nearest_sphere` of `nearest_list`), if it is nearer than every
    // other hit: its Hit is filled at the end.
    const ShapeList* nearest_list = nullptr;
    std::uint32_t nearest_sphere = 0;
    double nearest_sphere_t = 0;
    const auto test = [&](const ShapeList& list, std::uint32_t i, double& t_limit) {
        const LeafSphere& sphere = list.spheres[i];
        if (sphere.radius > 0) {
            double t = 0;
            if (!sphere_hit_t(sphere.center, sphere.radius, ray, t_limit, t)) {
                return false;
            }
            t_limit = t;
            nearest_sphere_t = t;
            nearest_list = &list;
            nearest_sphere = i;
            return true;
        }
        if (!list.shapes[i]->intersect(ray, t_limit, hit)) {
            return false;
        }
        t_limit = hit.t;
        hit.primitive = list.scene_index[i];
        nearest_list = nullptr;
        return true;
    };
    bool found = false;
    for (std::uint32_t i = 0; i < direct_.size(); ++i) {
        found |= test(direct_, i, t_max);
    }
    if (leaves_.size() > 0) {
        found |=
            bvh_.intersect(ray, t_max, [&](std::uint32_t first, std::uint32_t count, double& t_limit, auto) {
                bool any = false;
                for (std::uint32_t i = first; i < first + count; ++i) {
                    any |= test(leaves_, i, t_limit);
                }
                return any;
            });
    }
    if (nearest_list != nullptr) {
        // The sphere's own intersect would find the same t; it fills the rest of the Hit from it.
        static_cast<const Sphere*>(nearest_list->shapes[nearest_sphere])
            ->fill_hit(ray, nearest_sphere_t, hit);
        hit.primitive = nearest_list->scene_index[nearest_sphere];
    }
    return found;
}

bool BvhAccelerator::occluded(const Ray& ray, double t_max) const {
    const auto occludes = [&](const ShapeList& list, std::uint32_t i, double t_limit) {
        const LeafSphere& sphere = list.spheres[i];
        return sphere.radius > 0 ? sphere_occludes(sphere.center, sphere.radius, ray, t_limit)
                                 : list.shapes[i]->occluded(ray, t_limit);
    };
    for (std::uint32_t i = 0; i < direct_.size(); ++i) {
        if (occludes(direct_, i, t_max)) {
            return true;
        }
    }
    return leaves_.size() > 0 &&
           bvh_.occluded(ray, t_max,
                         [&](std::uint32_t first, std::uint32_t count, double t_limit, auto /*avx2*/) {
                             for (std::uint32_t i = first; i < first + count; ++i) {
                                 if (occludes(leaves_, i, t_limit)) {
                                     return true;
                                 }
                             }
                             return false;
                         });
}

}  // namespace glint
