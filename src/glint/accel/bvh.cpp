#include "glint/accel/bvh.hpp"

#include <chrono>

namespace glint {

BvhAccelerator::BvhAccelerator(std::span<const Shape* const> shapes) : all_(shapes.begin(), shapes.end()) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<Bounds3> boxes;
    std::vector<std::uint32_t> bounded;
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const Bounds3 b = shapes[i]->bounds();
        bounds_.grow(b);
        if (b.is_finite()) {
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
        shapes_.push_back(shapes[bounded[position]]);
        shape_index_.push_back(bounded[position]);
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
    found |= bvh_.intersect(ray, t_max,
                            [&](std::uint32_t first, std::uint32_t count, double& t_limit, auto /*avx2*/) {
                                bool any = false;
                                for (std::uint32_t i = first; i < first + count; ++i) {
                                    if (shapes_[i]->intersect(ray, t_limit, hit)) {
                                        t_limit = hit.t;
                                        hit.primitive = shape_index_[i];
                                        any = true;
                                    }
                                }
                                return any;
                            });
    return found;
}

bool BvhAccelerator::occluded(const Ray& ray, double t_max) const {
    for (std::uint32_t i : direct_) {
        if (all_[i]->occluded(ray, t_max)) {
            return true;
        }
    }
    return bvh_.occluded(ray, t_max,
                         [&](std::uint32_t first, std::uint32_t count, double t_limit, auto /*avx2*/) {
                             for (std::uint32_t i = first; i < first + count; ++i) {
                                 if (shapes_[i]->occluded(ray, t_limit)) {
                                     return true;
                                 }
                             }
                             return false;
                         });
}

}  // namespace glint
