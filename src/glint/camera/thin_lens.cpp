// Thin lens {type: thin-lens, eye, look_at, up, fov | view_distance + zoom, near, near_shape,
//            lens_radius | f_stop + focal_length, focus_distance}.
#include "glint/camera/thin_lens.hpp"

#include "glint/params/params.hpp"
#include "glint/sampling/warps.hpp"

namespace glint {

Ray ThinLensCamera::generate_ray(Point2 film, Point2 lens) const {
    // The pinhole ray's direction has component d along −w, so scaling it by z_f/d reaches the focus
    // plane: every ray of this film point, whatever its lens point, passes there.
    const Vec3 to_focus = view_plane_direction(view_, film_, film) * (focus_distance_ / view_.view_distance);
    const Point2 disk = square_to_disk_concentric(lens);
    const Vec3 lens_offset = lens_radius_ * (disk.x * view_.basis.u + disk.y * view_.basis.v);
    // The lens offset lies across w, so the direction still advances focus_distance along the view.
    return ray_from_near_surface(view_, view_.eye + lens_offset, to_focus - lens_offset, focus_distance_);
}

std::unique_ptr<Camera> ThinLensCamera::create(Params& params, const BuildContext&, FilmSize film) {
    const ViewParams view = read_view_params(params, film);
    const bool has_radius = params.has("lens_radius");
    const bool has_f_stop = params.has("f_stop");
    const bool has_focal_length = params.has("focal_length");
    double lens_radius = 0;
    if (has_radius) {
        if (has_f_stop || has_focal_length) {
            params.fail(has_f_stop ? "f_stop" : "focal_length",
                        "thin-lens takes lens_radius, or f_stop with focal_length, not both");
        }
        lens_radius = params.non_negative("lens_radius", 0);
    } else if (has_f_stop || has_focal_length) {
        if (!has_f_stop || !has_focal_length) {
            params.fail(
                has_f_stop ? "f_stop" : "focal_length",
                "thin-lens f_stop and focal_length go together (lens_radius = focal_length / (2 f_stop))");
        }
        lens_radius = lens_radius_from_f_stop(params.positive("focal_length"), params.positive("f_stop"));
    } else {
        params.fail("thin-lens needs an aperture: lens_radius, or f_stop with focal_length");
    }
    const double focus_distance = params.positive("focus_distance", length(view.look_at - view.eye));
    if (has_focal_length && !(focus_distance > params.positive("focal_length"))) {
        params.fail(params.has("focus_distance") ? "focus_distance" : "focal_length",
                    "thin-lens focus_distance must exceed focal_length: a lens cannot focus nearer than f");
    }
    return std::make_unique<ThinLensCamera>(view, film, lens_radius, focus_distance);
}

}  // namespace glint
