// What every shape can do as a light: sampling by area, seen from a point.
#include "glint/geometry/shape.hpp"

namespace glint {

std::optional<SeenSample> Shape::sample_seen_from(const Vec3& ref, Point2 u) const {
    const std::optional<ShapeSample> s = sample_area(u);
    return s ? seen_from(ref, *s) : std::nullopt;
}

double Shape::pdf_seen_from(const Vec3& ref, const Vec3& wi, const Hit& on_shape) const {
    // sample_area() is uniform: its density is 1 / area everywhere.
    const double cos_at_point = std::abs(dot(on_shape.normal, wi));
    if (cos_at_point == 0 || !(area() > 0)) {
        return 0;
    }
    return length_squared(on_shape.point - ref) / (cos_at_point * area());
}

}  // namespace glint
