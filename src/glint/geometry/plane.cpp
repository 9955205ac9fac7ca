// Plane {type: plane, point: [x, y, z], normal: [x, y, z]}: infinite, two-sided.
#include "glint/geometry/plane.hpp"

#include "glint/core/frame.hpp"
#include "glint/params/params.hpp"

namespace glint {

Plane::Plane(const Vec3& point, const Vec3& normal) : point_(point), normal_(normalize(normal)) {
    const Frame frame = Frame::from_normal(normal_);
    tangent_ = frame.s;
    bitangent_ = frame.t;
}

double Plane::solve(const Ray& ray) const {
    const double denominator = dot(ray.direction, normal_);
    if (denominator == 0) {
        return kInf;  // parallel: no hit, even for a ray inside the plane
    }
    return dot(point_ - ray.origin, normal_) / denominator;
}

bool Plane::intersect(const Ray& ray, double t_max, Hit& hit) const {
    const double t = solve(ray);
    if (!(t > 0) || t >= t_max) {
        return false;
    }
    // Project onto the plane, so the point's error does not grow with t.
    Vec3 p = ray.at(t);
    p -= normal_ * dot(p - point_, normal_);
    hit.t = t;
    hit.point = p;
    hit.normal = normal_;
    hit.shading_normal = normal_;
    const Vec3 local = p - point_;
    hit.uv = {dot(local, tangent_), dot(local, bitangent_)};
    hit.error = kHitRelativeError * (max_component(abs(p)) + max_component(abs(point_)));
    return true;
}

bool Plane::occluded(const Ray& ray, double t_max) const {
    const double t = solve(ray);
    return t > 0 && t < t_max;
}

std::unique_ptr<Shape> Plane::create(Params& params, const BuildContext&) {
    const Vec3 point = params.vec3("point", {0, 0, 0});
    const Vec3 normal = params.direction("normal");
    return std::make_unique<Plane>(point, normal);
}

}  // namespace glint
