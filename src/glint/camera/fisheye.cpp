// Fisheye {type: fisheye, eye, look_at, up, fov}.
#include "glint/camera/fisheye.hpp"

#include "glint/core/math.hpp"
#include "glint/params/params.hpp"

namespace glint {

Ray FisheyeCamera::generate_ray(Point2 film, Point2) const {
    const double circle_radius = 0.5 * std::min(film_.width, film_.height);
    const double x = (film.x - 0.5 * film_.width) / circle_radius;
    const double y = (0.5 * film_.height - film.y) / circle_radius;
    const double r = std::hypot(x, y);
    if (r > 1) {
        return {view_.eye, Vec3{}};
    }
    const double theta = r * 0.5 * fov_;  // equidistant: angle ∝ radius
    const CameraBasis& b = view_.basis;
    // (x, y)/r is the unit direction in the image plane; at the centre (r = 0) any will do.
    const double sin_over_r = r > 0 ? std::sin(theta) / r : 0;
    return {view_.eye, sin_over_r * (x * b.u + y * b.v) - std::cos(theta) * b.w};
}

std::unique_ptr<Camera> FisheyeCamera::create(Params& params, const BuildContext&, FilmSize film) {
    const ViewFrame view = read_view_frame(params);
    const double fov = params.number("fov", 180.0);
    if (!(fov > 0 && fov <= 360)) {
        params.fail("fov", "fisheye fov is the angle across the image circle in degrees: in (0, 360]");
    }
    return std::make_unique<FisheyeCamera>(view, film, radians(fov));
}

}  // namespace glint
