#pragma once

#include "glint/accel/accelerator.hpp"

namespace glint {

// Tests every shape: O(n) per ray. The reference the faster accelerators are checked against.
class LinearAccelerator final : public Accelerator {
public:
    explicit LinearAccelerator(std::span<const Shape* const> shapes);
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    Bounds3 bounds() const override { return bounds_; }

private:
    std::vector<const Shape*> shapes_;
    Bounds3 bounds_;
};

}  // namespace glint
