#include "glint/camera/camera.hpp"

#include <cassert>

#include "glint/core/math.hpp"
#include "glint/params/params.hpp"

namespace glint {

namespace {
bool parallel(const Vec3& up, const Vec3& w) {
    return length(cross(up, w)) <= 1e-9 * length(up);
}
}  // namespace

void Camera::generate_rays(std::span<const Point2> film, std::span<const Point2> lens,
                           std::span<Ray> rays) const {
    assert(film.size() == rays.size() && lens.size() == rays.size());
    for (std::size_t i = 0; i < rays.size(); ++i) {
        rays[i] = generate_ray(film[i], lens[i]);
    }
}

CameraBasis camera_basis(const Vec3& eye, const Vec3& look_at, const Vec3& up) {
    CameraBasis b;
    b.w = normalize(eye - look_at);
    Vec3 chosen_up = up;
    if (parallel(up, b.w)) {
        b.up_was_degenerate = true;
        chosen_up = std::abs(b.w.y) > 0.5 ? Vec3{0, 0, b.w.y > 0 ? -1.0 : 1.0} : Vec3{0, 1, 0};
    }
    b.u = normalize(cross(chosen_up, b.w));
    b.v = cross(b.w, b.u);
    return b;
}

ViewFrame read_view_frame(Params& params) {
    ViewFrame view;
    view.eye = params.vec3("eye", {0, 0, 5});
    view.look_at = params.vec3("look_at", {0, 0, 0});
    if (length_squared(view.eye - view.look_at) == 0) {
        params.fail("look_at", "camera look_at must differ from eye (the view direction is look_at − eye)");
    }
    const bool up_given = params.has("up");
    const Vec3 up = params.direction("up", {0, 1, 0});
    view.basis = camera_basis(view.eye, view.look_at, up);
    if (view.basis.up_was_degenerate && up_given) {
        params.fail("up",
                    "camera up is parallel to the view direction, so it sets no roll; choose an up across "
                    "the view (or leave it out for the default)");
    }
    return view;
}

ViewParams read_view_params(Params& params, FilmSize film) {
    const ViewFrame frame = read_view_frame(params);
    ViewParams view;
    view.eye = frame.eye;
    view.look_at = frame.look_at;
    view.basis = frame.basis;
    const bool has_fov = params.has("fov");
    const bool has_distance = params.has("view_distance");
    if (has_fov && has_distance) {
        params.fail("view_distance", "camera takes fov or view_distance, not both");
    }
    const double zoom = params.positive("zoom", 1.0);
    view.pixel_size = 1.0 / zoom;
    if (has_distance) {
        view.view_distance = params.positive("view_distance");
    } else {
        const double fov = params.number("fov", 40.0);
        if (!(fov > 0 && fov < 180)) {
            params.fail("fov",
                        "camera fov is the vertical field of view in degrees: between 0 and 180, exclusive");
        }
        // The view plane at distance d shows height/2 pixels above the centre: tan(fov/2) = (h/2)/d.
        view.view_distance = 0.5 * film.height / std::tan(radians(fov) / 2);
    }
    // A near clipping surface, as smallpt's camera has (its rays start 140 units out, past a wall).
    view.near = params.non_negative("near", 0.0);
    static const EnumTable<NearShape> near_shapes = {{"plane", NearShape::Plane},
                                                     {"sphere", NearShape::Sphere}};
    view.near_shape = params.enumeration("near_shape", near_shapes, NearShape::Plane);
    return view;
}

}  // namespace glint
