#pragma once

#include "glint/camera/camera.hpp"

namespace glint {

// The virtual pinhole camera of paper §IV: every ray starts at the eye and passes through a point of
// the view plane at distance d along −w; the plane's pixels are pixel_size (1/zoom) wide. With a near
// distance (`near` > 0) the ray starts where it crosses the near plane across w at `near` from the eye
// (or, near_shape sphere, at distance `near` along itself).
class PinholeCamera final : public Camera {
  public:
    PinholeCamera(const ViewParams& view, FilmSize film) : view_(view), film_(film) {}
    Ray generate_ray(Point2 film, Point2 lens) const override;
    // The base's loop with generate_ray inline instead of a virtual call per ray: the same bits, 0.6 % of
    // the Cornell box's instructions (bench/ab.py: 0.987 of its time, smallpt's scene 0.994).
    void generate_rays(std::span<const Point2> film, std::span<const Point2> lens,
                       std::span<Ray> rays) const override;
    bool uses_lens() const override { return false; }

    static std::unique_ptr<Camera> create(Params& params, const BuildContext& context, FilmSize film);

  private:
    ViewParams view_;
    FilmSize film_;
};

}  // namespace glint
