// Pinhole {type: pinhole, eye, look_at, up, fov | view_distance + zoom}.
#include "glint/camera/pinhole.hpp"

#include "glint/params/params.hpp"

namespace glint {

Ray PinholeCamera::generate_ray(Point2 film, Point2) const {
    return {view_.eye, normalize(view_plane_direction(view_, film_, film))};
}

std::unique_ptr<Camera> PinholeCamera::create(Params& params, const BuildContext&, FilmSize film) {
    return std::make_unique<PinholeCamera>(read_view_params(params, film), film);
}

}  // namespace glint
