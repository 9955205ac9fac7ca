// Pinhole {type: pinhole, eye, look_at, up, fov | view_distance + zoom, near, near_shape}.
#include "glint/camera/pinhole.hpp"

#include "glint/params/params.hpp"

namespace glint {

Ray PinholeCamera::generate_ray(Point2 film, Point2) const {
    // view_plane_direction advances d = view_distance along the view per unit.
    return ray_from_near_surface(view_, view_.eye, view_plane_direction(view_, film_, film),
                                 view_.view_distance);
}

void PinholeCamera::generate_rays(std::span<const Point2> film, std::span<const Point2> lens,
                                  std::span<Ray> rays) const {
    for (std::size_t i = 0; i < rays.size(); ++i) {
        rays[i] = PinholeCamera::generate_ray(film[i], lens[i]);
    }
}

std::unique_ptr<Camera> PinholeCamera::create(Params& params, const BuildContext&, FilmSize film) {
    return std::make_unique<PinholeCamera>(read_view_params(params, film), film);
}

}  // namespace glint
