#pragma once

#include "glint/core/transform.hpp"
#include "glint/geometry/shape.hpp"

namespace glint {

// A shape placed by an affine transform: rays move into the shape's own space, hits move back out.
// The ray's direction is transformed without normalising, so t is the same in both spaces.
class Instance final : public Shape {
  public:
    Instance(std::unique_ptr<Shape> shape, const Transform& to_world)
        : shape_(std::move(shape)), to_world_(to_world) {}
    Bounds3 bounds() const override { return to_world_.bounds(shape_->bounds()); }
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    // Only for similarity transforms (rotation, uniform scale, mirror, translation): other affine maps
    // stretch areas unevenly, so the shape's uniform samples would no longer be uniform. Otherwise 0
    // and no sample, like an unbounded shape.
    double area() const override;
    std::optional<ShapeSample> sample_area(Point2 u) const override;

    const Transform& transform() const { return to_world_; }
    const Shape& shape() const { return *shape_; }  // the shape in its own space

  private:
    Ray to_object(const Ray& ray) const {
        return {to_world_.inverse_point(ray.origin), to_world_.inverse_vector(ray.direction)};
    }

    std::unique_ptr<Shape> shape_;
    Transform to_world_;
};

// The object's `transform` key, if present, wraps its shape in an Instance (else the shape is returned
// as it is). Bad transforms (a zero scale, a singular matrix, unknown keys) are positioned errors.
std::unique_ptr<Shape> apply_transform(Params& object, std::unique_ptr<Shape> shape);

}  // namespace glint
