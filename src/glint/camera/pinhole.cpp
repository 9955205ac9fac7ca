// Pinhole {type: pinhole, eye, look_at, up, fov | view_distance + zoom}.
#include "glint/camera/pinhole.hpp"

#include "glint/scene/params.hpp"

namespace glint {

Ray PinholeCamera::generate_ray(Point2 film, Point2) const {
    const double x = view_.pixel_size * (film.x - 0.5 * film_.width);
    const double y = view_.pixel_size * (0.5 * film_.height - film.y);
    const CameraBasis& b = view_.basis;
    return {view_.eye, normalize(x * b.u + y * b.v - view_.view_distance * b.w)};
}

std::unique_ptr<Camera> PinholeCamera::create(Params& params, const BuildContext&, FilmSize film) {
    return std::make_unique<PinholeCamera>(read_view_params(params, film), film);
}

}  // namespace glint
