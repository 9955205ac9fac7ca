// Box {type: box, min: [x, y, z], max: [x, y, z]}: axis-aligned, min < max on every axis.
// uv on each face: the two other coordinates, as fractions of the box's extent, in axis order.
#include "glint/geometry/box.hpp"

#include "glint/params/params.hpp"

namespace glint {

namespace {
// The other two axes of a face, in increasing order.
constexpr int kOther[3][2] = {{1, 2}, {0, 2}, {0, 1}};
}  // namespace

double Box::solve(const Ray& ray, double t_max, int& axis, int& side) const {
    // The slab method: the ray is inside the box for t in [t_enter, t_exit].
    double t_enter = -kInf, t_exit = kInf;
    int enter_axis = -1, exit_axis = -1;
    for (int i = 0; i < 3; ++i) {
        const double o = ray.origin[i];
        const double d = ray.direction[i];
        // The near and far planes picked by the direction's sign, not by comparing the two t's: the
        // same doubles (a division by d < 0 reverses their order), and the divisions need not wait for
        // the comparison. Along a slab's planes (d = ±0) the t's are ±∞, which end the ray outside the
        // slab and limit nothing inside it, or 0/0 = NaN on a plane itself, which compares false below
        // and so limits nothing either. (Picking the planes by an index instead of the sign's branch
        // was 5 % slower on book 2's Cornell box: the loads then wait for the direction.)
        const bool negative = std::signbit(d);
        const double t_near = ((negative ? max_[i] : min_[i]) - o) / d;
        const double t_far = ((negative ? min_[i] : max_[i]) - o) / d;
        if (t_near > t_enter) {
            t_enter = t_near;
            enter_axis = i;
        }
        if (t_far < t_exit) {
            t_exit = t_far;
            exit_axis = i;
        }
    }
    if (t_enter > t_exit) {
        return kInf;
    }
    // From outside the first hit is where the ray enters; from inside (t_enter ≤ 0) where it leaves.
    // (A ray outside a slab it runs along has t_enter = +∞ or t_exit = −∞: no t below passes.)
    const bool entering = t_enter > 0;
    const double t = entering ? t_enter : t_exit;
    axis = entering ? enter_axis : exit_axis;
    if (!(t > 0) || t >= t_max || axis < 0) {
        return kInf;
    }
    // Entering through a face means moving against its outward normal.
    side = (ray.direction[axis] > 0) == entering ? -1 : 1;
    return t;
}

bool Box::intersect(const Ray& ray, double t_max, Hit& hit) const {
    int face = 0;
    return intersect_face(ray, t_max, hit, face);
}

bool Box::intersect_face(const Ray& ray, double t_max, Hit& hit, int& face) const {
    int axis = 0, side = 0;
    const double t = solve(ray, t_max, axis, side);
    if (t == kInf) {
        return false;
    }
    // Put the point exactly on its face and inside the face's rectangle.
    Vec3 p = ray.at(t);
    p[axis] = side < 0 ? min_[axis] : max_[axis];
    Vec3 normal;
    normal[axis] = side;
    const int a = kOther[axis][0], b = kOther[axis][1];
    p[a] = std::clamp(p[a], min_[a], max_[a]);
    p[b] = std::clamp(p[b], min_[b], max_[b]);
    hit.t = t;
    hit.point = p;
    hit.normal = normal;
    hit.shading_normal = normal;
    hit.uv = {(p[a] - min_[a]) / (max_[a] - min_[a]), (p[b] - min_[b]) / (max_[b] - min_[b])};
    hit.error = kHitRelativeError * (max_component(abs(p)) + max_abs_corner_);
    face = side < 0 ? axis : axis + 3;
    return true;
}

bool Box::occluded(const Ray& ray, double t_max) const {
    int axis = 0, side = 0;
    return solve(ray, t_max, axis, side) != kInf;
}

double Box::area() const {
    const Vec3 e = max_ - min_;
    return 2 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

std::optional<ShapeSample> Box::sample_area(Point2 u) const {
    // Choose one of the six faces with probability proportional to its area, reusing u.x rescaled
    // to [0, 1) within the chosen face's share, then a uniform point on that face.
    const Vec3 e = max_ - min_;
    const double half_area = e.y * e.z + e.x * e.z + e.x * e.y;
    double x = u.x * 2 * half_area;
    int face = 0;  // 0–2: the min faces of x, y, z; 3–5: the max faces
    double face_area = 0;
    for (; face < 6; ++face) {
        const int axis = face % 3;
        face_area = e[kOther[axis][0]] * e[kOther[axis][1]];
        if (x < face_area || face == 5) {
            break;
        }
        x -= face_area;
    }
    const int axis = face % 3;
    const int a = kOther[axis][0], b = kOther[axis][1];
    Vec3 p, normal;
    p[axis] = face < 3 ? min_[axis] : max_[axis];
    normal[axis] = face < 3 ? -1 : 1;
    p[a] = min_[a] + e[a] * std::clamp(x / face_area, 0.0, 1.0);
    p[b] = min_[b] + e[b] * u.y;
    return ShapeSample{p, normal, 1 / area()};
}

std::unique_ptr<Shape> Box::create(Params& params, const BuildContext&) {
    const Vec3 min = params.vec3("min");
    const Vec3 max = params.vec3("max");
    for (int i = 0; i < 3; ++i) {
        if (!(min[i] < max[i])) {
            // Quote the numbers as written: the user recognises them.
            const std::string axis(1, "xyz"[i]);
            params.fail("max", "box max." + axis + " (" + params.node("max")->items[i].scalar +
                                   ") must be greater than min." + axis + " (" +
                                   params.node("min")->items[i].scalar +
                                   "): a box needs min < max on every axis");
        }
    }
    return std::make_unique<Box>(min, max);
}

}  // namespace glint
