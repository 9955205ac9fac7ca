#pragma once

#include "glint/camera/camera.hpp"

namespace glint {

// The 360° panorama in the equirectangular (latitude–longitude) projection: x spans longitude −180° …
// 180° left to right with look_at at the image centre, y spans latitude 90° (up) … −90° top to bottom.
// Pixels are square angles when the image is twice as wide as high. All rays start at the eye.
//
// Parameters: eye, look_at, up (as the pinhole); `up` is the panorama's zenith.
class SphericalCamera final : public Camera {
  public:
    SphericalCamera(const ViewFrame& view, FilmSize film) : view_(view), film_(film) {}
    Ray generate_ray(Point2 film, Point2 lens) const override;
    bool uses_lens() const override { return false; }

    static std::unique_ptr<Camera> create(Params& params, const BuildContext& context, FilmSize film);

  private:
    ViewFrame view_;
    FilmSize film_;
};

}  // namespace glint
