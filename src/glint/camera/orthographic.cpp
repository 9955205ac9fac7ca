// Orthographic {type: orthographic, eye, look_at, up, height}.
#include "glint/camera/orthographic.hpp"

#include "glint/params/params.hpp"

namespace glint {

Ray OrthographicCamera::generate_ray(Point2 film, Point2) const {
    const double x = scale_ * (film.x - 0.5 * film_.width);
    const double y = scale_ * (0.5 * film_.height - film.y);
    const CameraBasis& b = view_.basis;
    return {view_.eye + x * b.u + y * b.v, -b.w};
}

std::unique_ptr<Camera> OrthographicCamera::create(Params& params, const BuildContext&, FilmSize film) {
    const ViewFrame view = read_view_frame(params);
    return std::make_unique<OrthographicCamera>(view, film, params.positive("height", 2.0));
}

}  // namespace glint
