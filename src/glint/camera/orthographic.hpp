#pragma once

#include "glint/camera/camera.hpp"

namespace glint {

// The orthographic (parallel) camera: every ray goes along −w, from a point of the plane through the
// eye across the view direction, so sizes do not shrink with distance. Only what lies in front of that
// plane is seen.
//
// Parameters: eye, look_at, up (as the pinhole), and
//   height   the height of the view in scene units (default 2); the width follows the image's aspect.
class OrthographicCamera final : public Camera {
  public:
    OrthographicCamera(const ViewFrame& view, FilmSize film, double view_height)
        : view_(view), film_(film), scale_(view_height / film.height) {}
    Ray generate_ray(Point2 film, Point2 lens) const override;
    bool uses_lens() const override { return false; }

    static std::unique_ptr<Camera> create(Params& params, const BuildContext& context, FilmSize film);

  private:
    ViewFrame view_;
    FilmSize film_;
    double scale_;  // scene units per pixel
};

}  // namespace glint
