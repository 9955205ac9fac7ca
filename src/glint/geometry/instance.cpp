// Instances: any object may carry `transform`, which places it by an affine map. Either one map,
//   transform: {scale: 2 or [sx, sy, sz], rotate: {axis: [x, y, z], angle: degrees}, translate: [x, y, z]}
// applied as scale, then rotate, then translate whatever the order of the keys (each key optional), or
//   transform: {matrix: [12 or 16 numbers]}   (row-major; a 16-number matrix must end in 0, 0, 0, 1)
// or a list of such maps, applied in list order: [{rotate: …}, {translate: …}, {scale: …}].
// An ellipsoid is a sphere with scale [a, b, c].
#include "glint/geometry/instance.hpp"

#include "glint/params/params.hpp"

namespace glint {

Instance::Instance(std::unique_ptr<Shape> shape, const Transform& to_world)
    : shape_(std::move(shape)),
      to_world_(to_world),
      uniform_scale_(to_world.uniform_scale()),
      // The triple product of the images of the axes, the columns of M.
      abs_determinant_(std::abs(
          dot(to_world.vector({1, 0, 0}), cross(to_world.vector({0, 1, 0}), to_world.vector({0, 0, 1}))))),
      max_row_abs_sum_(max_component(to_world.row_abs_sums())),
      max_abs_translation_(max_component(abs(to_world.translation()))),
      box_(dynamic_cast<const Box*>(shape_.get())) {
    for (int face = 0; face < 6; ++face) {
        Vec3 normal;  // as Box::intersect_face makes it
        normal[face % 3] = face < 3 ? -1 : 1;
        box_normals_[face] = normalize(to_world_.normal(normal));
    }
}

double Instance::world_error(double local_error, const Vec3& local_point, const Vec3& world_point) const {
    // The object-space error grows by at most the row sums of |M| in each axis, and transforming the
    // point rounds relative to the terms summed.
    return max_row_abs_sum_ * local_error +
           kHitRelativeError * (max_row_abs_sum_ * max_component(abs(local_point)) + max_abs_translation_ +
                                max_component(abs(world_point)));
}

bool Instance::intersect(const Ray& ray, double t_max, Hit& hit) const {
    if (box_ != nullptr) {
        // Straight into `hit` (the box leaves it untouched on a miss), without a virtual call, and the
        // normal from the table: the same Hit as below, without normalising two normals per hit.
        int face = 0;
        if (!box_->intersect_face(to_object(ray), t_max, hit, face)) {
            return false;
        }
        const Vec3 local_point = hit.point;
        hit.point = to_world_.point(local_point);
        hit.normal = box_normals_[face];
        hit.shading_normal = hit.normal;
        hit.error = world_error(hit.error, local_point, hit.point);
        hit.primitive = 0;  // as the fresh Hit below gives
        hit.element = 0;
        return true;
    }
    Hit local;
    if (!shape_->intersect(to_object(ray), t_max, local)) {
        return false;
    }
    hit = local;
    hit.uv = surface_uv(local);  // from the shape's own normal, before it is turned to world space
    hit.point = to_world_.point(local.point);
    hit.normal = normalize(to_world_.normal(local.normal));
    // Most shapes shade with their geometric normal: it needs turning only once.
    hit.shading_normal =
        local.shading_normal == local.normal ? hit.normal : normalize(to_world_.normal(local.shading_normal));
    hit.error = world_error(local.error, local.point, hit.point);
    return true;
}

bool Instance::occluded(const Ray& ray, double t_max) const {
    return box_ != nullptr ? box_->occluded(to_object(ray), t_max) : shape_->occluded(to_object(ray), t_max);
}

double Instance::area() const {
    return uniform_scale_ ? *uniform_scale_ * *uniform_scale_ * shape_->area() : 0;
}

std::optional<ShapeSample> Instance::sample_area(Point2 u) const {
    const double world_area = area();
    if (!(world_area > 0)) {
        return std::nullopt;
    }
    std::optional<ShapeSample> s = shape_->sample_area(u);
    if (!s) {
        return std::nullopt;
    }
    s->point = to_world_.point(s->point);
    s->normal = normalize(to_world_.normal(s->normal));
    s->pdf_area = 1 / world_area;
    return s;
}

double Instance::world_per_local_density(const Vec3& wi) const {
    // With v = M⁻¹ wi, the local direction is w = v / |v| and |M w| = 1 / |v|.
    const double stretch = length(to_world_.inverse_vector(wi));
    return 1 / (abs_determinant_ * stretch * stretch * stretch);
}

std::optional<SeenSample> Instance::sample_seen_from(const Vec3& ref, Point2 u) const {
    if (samples_world_area()) {
        return Shape::sample_seen_from(ref, u);
    }
    const std::optional<SeenSample> local = shape_->sample_seen_from(to_world_.inverse_point(ref), u);
    if (!local) {
        return std::nullopt;
    }
    const Vec3 point = to_world_.point(local->point);
    const Vec3 to_point = point - ref;
    const double distance = length(to_point);
    if (!(distance > 0)) {
        return std::nullopt;
    }
    const Vec3 wi = to_point / distance;
    return SeenSample{point, normalize(to_world_.normal(local->normal)), wi,
                      local->pdf_solid_angle * world_per_local_density(wi)};
}

double Instance::pdf_seen_from(const Vec3& ref, const Vec3& wi, const Hit& on_shape) const {
    if (samples_world_area()) {
        return Shape::pdf_seen_from(ref, wi, on_shape);
    }
    // The hit in the shape's space: normals move back by Mᵀ, the inverse of the inverse transpose.
    Hit local;
    local.point = to_world_.inverse_point(on_shape.point);
    local.normal = normalize(to_world_.inverse().normal(on_shape.normal));
    local.shading_normal = local.normal;
    const Vec3 local_wi = normalize(to_world_.inverse_vector(wi));
    return shape_->pdf_seen_from(to_world_.inverse_point(ref), local_wi, local) * world_per_local_density(wi);
}

namespace {

Transform read_matrix(Params& step) {
    const Node* node = step.node("matrix");
    const std::string what = step.what() + ".matrix";
    if (!node->is_sequence() || (node->items.size() != 12 && node->items.size() != 16)) {
        throw SceneError(
            node->pos,
            what + " must be a list of 12 or 16 numbers (3 or 4 rows of 4, row by row), not " +
                (node->is_sequence() ? std::to_string(node->items.size()) + " numbers" : node->describe()));
    }
    Transform::Matrix m{};
    for (int i = 0; i < 12; ++i) {
        m[i / 4][i % 4] = node_number(node->items[i], what + "[" + std::to_string(i) + "]");
    }
    if (node->items.size() == 16) {
        const double last_row[4] = {0, 0, 0, 1};
        for (int j = 0; j < 4; ++j) {
            const Node& item = node->items[12 + j];
            if (node_number(item, what + "[" + std::to_string(12 + j) + "]") != last_row[j]) {
                throw SceneError(item.pos, what +
                                               " must be affine: its last row must be 0, 0, 0, 1 (projective "
                                               "transforms are not supported)");
            }
        }
    }
    const std::optional<Transform> t = Transform::from_matrix(m);
    if (!t) {
        step.fail("matrix",
                  what + " cannot be inverted (it flattens space, so the object would have no normals)");
    }
    return *t;
}

// One map: a matrix, or scale then rotate then translate.
Transform read_step(const Node& node, const std::string& what) {
    Params step(node, what);
    Transform t;
    if (step.has("matrix")) {
        for (const char* other : {"scale", "rotate", "translate"}) {
            if (step.has(other)) {
                step.fail(other, what + " has both matrix and " + other +
                                     ": give them as separate steps of a list, in the order they apply");
            }
        }
        t = read_matrix(step);
    }
    if (const Node* scale = step.node("scale")) {
        const Vec3 s = scale->is_scalar() ? Vec3(1, 1, 1) * node_number(*scale, what + ".scale")
                                          : node_vec3(*scale, what + ".scale");
        const std::optional<Transform> scaling = Transform::scale(s);
        if (!scaling) {
            throw SceneError(scale->pos, what +
                                             ".scale must not be zero in any axis (a flattened object has "
                                             "no normals); negative values mirror");
        }
        t = t.then(*scaling);
    }
    if (step.has("rotate")) {
        Params rotate = step.child("rotate");
        const Vec3 axis = rotate.direction("axis");
        const double angle = rotate.number("angle");
        rotate.finish();
        t = t.then(Transform::rotate(axis, angle));
    }
    if (step.has("translate")) {
        t = t.then(Transform::translate(step.vec3("translate")));
    }
    step.finish();
    return t;
}

}  // namespace

std::unique_ptr<Shape> apply_transform(Params& object, std::unique_ptr<Shape> shape) {
    const Node* node = object.node("transform");
    if (!node) {
        return shape;
    }
    const std::string what = object.what() + ".transform";
    Transform t;
    if (node->is_sequence()) {
        for (size_t i = 0; i < node->items.size(); ++i) {
            t = t.then(read_step(node->items[i], what + "[" + std::to_string(i) + "]"));
        }
    } else if (node->is_map()) {
        t = read_step(*node, what);
    } else {
        throw SceneError(node->pos, what +
                                        " must be a map {scale, rotate, translate} or {matrix}, or a list of "
                                        "such maps, not " +
                                        node->describe());
    }
    // Steps that are each invertible can still compose to a transform too close to singular.
    if (!Transform::from_matrix(t.matrix())) {
        throw SceneError(node->pos, what + " cannot be inverted (it flattens space)");
    }
    return std::make_unique<Instance>(std::move(shape), t);
}

}  // namespace glint
