#pragma once

#include <array>

#include "glint/core/transform.hpp"
#include "glint/geometry/box.hpp"
#include "glint/geometry/shape.hpp"

namespace glint {

// A shape placed by an affine transform: rays move into the shape's own space, hits move back out.
// The ray's direction is transformed without normalising, so t is the same in both spaces.
class Instance final : public Shape {
  public:
    Instance(std::unique_ptr<Shape> shape, const Transform& to_world);
    Bounds3 bounds() const override { return to_world_.bounds(shape_->bounds()); }
    bool intersect(const Ray& ray, double t_max, Hit& hit) const override;
    bool occluded(const Ray& ray, double t_max) const override;
    // Only for similarity transforms (rotation, uniform scale, mirror, translation): other affine maps
    // stretch areas unevenly, so the shape's uniform samples would no longer be uniform. Otherwise 0
    // and no sample, like an unbounded shape (so the scene refuses such an object as a light, although
    // sample_seen_from() below samples it exactly).
    double area() const override;
    std::optional<ShapeSample> sample_area(Point2 u) const override;

    // Seen from a point: a shape that samples by area is sampled by area here, in world space, when the
    // transform is a similarity (the same distribution as in its own space, without moving the reference
    // point in and the density out). Otherwise the shape samples itself in its own space, seen from the
    // reference point moved there (a sphere by its cone, an ellipsoid so by the cone of its unit
    // sphere), and the sample moves out. Any affine map x ↦ M x + b takes the directions from the
    // reference point to the directions from its image by w ↦ M w / |M w|, whose Jacobian is
    // |det M| / |M w|³: the density is divided by it, so it is exact for scale and shear too.
    std::optional<SeenSample> sample_seen_from(const Vec3& ref, Point2 u) const override;
    double pdf_seen_from(const Vec3& ref, const Vec3& wi, const Hit& on_shape) const override;
    bool samples_by_area() const override { return samples_world_area(); }

    const Transform& transform() const { return to_world_; }
    const Shape& shape() const { return *shape_; }  // the shape in its own space

  private:
    Ray to_object(const Ray& ray) const {
        return {to_world_.inverse_point(ray.origin), to_world_.inverse_vector(ray.direction)};
    }

    // The world-space error bound of a hit at world_point, from its error and point in the shape's space.
    double world_error(double local_error, const Vec3& local_point, const Vec3& world_point) const;

    // Whether sample_seen_from() samples this instance by area in world space (see there).
    bool samples_world_area() const { return uniform_scale_ && shape_->samples_by_area(); }
    // The solid-angle density in world space per density in the shape's space, for the world direction
    // wi (unit): 1 / (|det M| |M⁻¹ wi|³).
    double world_per_local_density(const Vec3& wi) const;

    std::unique_ptr<Shape> shape_;
    Transform to_world_;
    std::optional<double> uniform_scale_;  // to_world_.uniform_scale()
    double abs_determinant_;               // |det M| of the linear part
    // Per transform, not per hit: the largest row sum of |M| and the largest |translation|.
    double max_row_abs_sum_;
    double max_abs_translation_;
    // When the shape is a Box (rotated boxes are common): the box, called directly, and the world normal
    // of each of its faces (numbered as Box::intersect_face does), as intersect() would compute it.
    const Box* box_;
    std::array<Vec3, 6> box_normals_{};
};

// The object's `transform` key, if present, wraps its shape in an Instance (else the shape is returned
// as it is). Bad transforms (a zero scale, a singular matrix, unknown keys) are positioned errors.
std::unique_ptr<Shape> apply_transform(Params& object, std::unique_ptr<Shape> shape);

}  // namespace glint
