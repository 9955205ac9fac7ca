// Rectangle {type: rectangle, corner: [x, y, z], edge1: [x, y, z], edge2: [x, y, z]}: the parallelogram
// spanned by two edges from a corner (a rectangle when they are perpendicular). Parallel or zero edges
// are an error. Normal = normalize(edge1 × edge2). uv = (a, b), the fractions along edge1 and edge2.
#include "glint/geometry/rectangle.hpp"

#include "glint/geometry/planar.hpp"
#include "glint/params/params.hpp"

namespace glint {

Rectangle::Rectangle(const Vec3& corner, const Vec3& edge1, const Vec3& edge2)
    : corner_(corner), edge1_(edge1), edge2_(edge2) {
    const Vec3 n = cross(edge1, edge2);
    const double n2 = length_squared(n);
    area_ = std::sqrt(n2);
    pdf_area_ = 1 / area_;
    normal_ = n / area_;
    // q·(edge2 × n) = a·edge1·(edge2 × n) = a·|n|², and likewise for b.
    dual1_ = cross(edge2, n) / n2;
    dual2_ = cross(n, edge1) / n2;
}

Bounds3 Rectangle::bounds() const {
    Bounds3 b;
    b.grow(corner_);
    b.grow(corner_ + edge1_);
    b.grow(corner_ + edge2_);
    b.grow(corner_ + edge1_ + edge2_);
    return b;
}

double Rectangle::solve(const Ray& ray, double t_max, Vec3& point, Point2& ab) const {
    const double t = plane_hit_t(ray, corner_, normal_);
    if (!(t > 0) || t >= t_max) {
        return kInf;
    }
    point = point_on_plane(ray, t, corner_, normal_);
    const Vec3 q = point - corner_;
    ab = {dot(q, dual1_), dot(q, dual2_)};
    if (ab.x < 0 || ab.x > 1 || ab.y < 0 || ab.y > 1) {
        return kInf;
    }
    return t;
}

bool Rectangle::intersect(const Ray& ray, double t_max, Hit& hit) const {
    Vec3 p;
    Point2 ab;
    const double t = solve(ray, t_max, p, ab);
    if (t == kInf) {
        return false;
    }
    fill_hit(t, p, ab, hit);
    return true;
}

void Rectangle::fill_hit(double t, const Vec3& point, Point2 ab, Hit& hit) const {
    hit.t = t;
    hit.point = point;
    hit.normal = normal_;
    hit.shading_normal = normal_;
    hit.uv = ab;
    hit.error = kHitRelativeError * (max_component(abs(point)) + max_component(abs(corner_)) +
                                     max_component(abs(edge1_)) + max_component(abs(edge2_)));
}

bool Rectangle::occluded(const Ray& ray, double t_max) const {
    Vec3 p;
    Point2 ab;
    return solve(ray, t_max, p, ab) != kInf;
}

std::unique_ptr<Shape> Rectangle::create(Params& params, const BuildContext&) {
    const Vec3 corner = params.vec3("corner");
    const Vec3 edge1 = params.vec3("edge1");
    const Vec3 edge2 = params.vec3("edge2");
    if (length_squared(edge1) == 0) {
        params.fail("edge1", "rectangle edge1 must not be zero");
    }
    if (length_squared(edge2) == 0) {
        params.fail("edge2", "rectangle edge2 must not be zero");
    }
    // Parallel edges span no area; "nearly parallel" is measured by the sine of their angle, so the
    // test does not depend on the scene's scale.
    const double sine = length(cross(edge1, edge2)) / (length(edge1) * length(edge2));
    if (!(sine > 1e-9)) {
        params.fail("edge2", "rectangle edge1 and edge2 are parallel: they span no area");
    }
    return std::make_unique<Rectangle>(corner, edge1, edge2);
}

}  // namespace glint
