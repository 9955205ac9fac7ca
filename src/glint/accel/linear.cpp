#include "glint/accel/linear.hpp"

namespace glint {

LinearAccelerator::LinearAccelerator(std::span<const Shape* const> shapes) : shapes_(shapes.begin(), shapes.end()) {
    for (const Shape* shape : shapes_) {
        bounds_.grow(shape->bounds());
    }
}

bool LinearAccelerator::intersect(const Ray& ray, double t_max, Hit& hit) const {
    bool found = false;
    for (std::size_t i = 0; i < shapes_.size(); ++i) {
        if (shapes_[i]->intersect(ray, t_max, hit)) {
            t_max = hit.t;
            hit.primitive = static_cast<std::uint32_t>(i);
            found = true;
        }
    }
    return found;
}

bool LinearAccelerator::occluded(const Ray& ray, double t_max) const {
    for (const Shape* shape : shapes_) {
        if (shape->occluded(ray, t_max)) {
            return true;
        }
    }
    return false;
}

}  // namespace glint
