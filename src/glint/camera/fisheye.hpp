#pragma once

#include "glint/camera/camera.hpp"

namespace glint {

// The equidistant fisheye: the angle of a ray from the view direction grows linearly with its film
// point's distance from the image centre, reaching fov/2 on the image circle, the largest circle the
// image holds (diameter min(width, height)). Film points outside the circle see nothing: they get the
// zero-direction ray (sees_scene() is false) and render black, as a real circular fisheye's corners do.
//
// Parameters: eye, look_at, up (as the pinhole), and
//   fov   the angle across the image circle in degrees, in (0, 360]; default 180 (a hemisphere).
class FisheyeCamera final : public Camera {
  public:
    FisheyeCamera(const ViewFrame& view, FilmSize film, double fov_radians)
        : view_(view), film_(film), fov_(fov_radians) {}
    Ray generate_ray(Point2 film, Point2 lens) const override;
    bool uses_lens() const override { return false; }

    static std::unique_ptr<Camera> create(Params& params, const BuildContext& context, FilmSize film);

  private:
    ViewFrame view_;
    FilmSize film_;
    double fov_;
};

}  // namespace glint
