// Spherical {type: spherical (or equirectangular), eye, look_at, up}.
#include "glint/camera/spherical.hpp"

#include "glint/core/math.hpp"
#include "glint/params/params.hpp"

namespace glint {

Ray SphericalCamera::generate_ray(Point2 film, Point2) const {
    const double longitude = 2 * kPi * (film.x / film_.width - 0.5);
    const double latitude = kPi * (0.5 - film.y / film_.height);
    const CameraBasis& b = view_.basis;
    // Longitude 0 is the view direction −w; positive longitudes turn right, towards u.
    const Vec3 horizontal = std::sin(longitude) * b.u - std::cos(longitude) * b.w;
    return {view_.eye, std::cos(latitude) * horizontal + std::sin(latitude) * b.v};
}

std::unique_ptr<Camera> SphericalCamera::create(Params& params, const BuildContext&, FilmSize film) {
    return std::make_unique<SphericalCamera>(read_view_frame(params), film);
}

}  // namespace glint
