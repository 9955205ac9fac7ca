#pragma once

#include "glint/camera/camera.hpp"

namespace glint {

// The thin-lens camera of paper §IV.1–2 (depth of field). The pinhole camera's view (fov or
// view_distance + zoom) picks, for each film point, a point on the focus plane — the plane across the
// view direction at focus_distance from the eye. Rays start on the lens, a disk of lens_radius about
// the eye across w, and pass through that point: what lies on the focus plane is sharp, anything at
// depth z (along the view direction) is spread over a disk of diameter 2·lens_radius·|z − z_f|/z on the
// focus plane (errata §4.1: the circle of confusion, measured on the object side).
//
// Parameters (besides the pinhole's):
//   lens_radius     radius of the aperture in scene units (0: a pinhole), or
//   f_stop          with focal_length: the f-number N = f/D, so lens_radius = f/(2N)
//   focal_length    f, in scene units (where the lens focuses parallel rays)
//   focus_distance  z_f, in scene units along the view direction; default ‖look_at − eye‖. With a
//                   focal_length it must exceed it (a lens cannot focus nearer than f).
//   near, near_shape  as the pinhole's: rays start where they cross the plane across w at `near` from
//                   the lens (the eye's plane), or at distance `near` along themselves.
class ThinLensCamera final : public Camera {
  public:
    ThinLensCamera(const ViewParams& view, FilmSize film, double lens_radius, double focus_distance)
        : view_(view), film_(film), lens_radius_(lens_radius), focus_distance_(focus_distance) {}
    Ray generate_ray(Point2 film, Point2 lens) const override;
    // Four rays at a time in AVX2 lanes, where the CPU has them: the same operations as generate_ray's,
    // lane by lane, so the same bits.
    void generate_rays(std::span<const Point2> film, std::span<const Point2> lens,
                       std::span<Ray> rays) const override;

    double lens_radius() const { return lens_radius_; }
    double focus_distance() const { return focus_distance_; }

    static std::unique_ptr<Camera> create(Params& params, const BuildContext& context, FilmSize film);

  private:
    ViewParams view_;
    FilmSize film_;
    double lens_radius_;
    double focus_distance_;
};

// The aperture radius of a lens of focal length f at f-number N: the diameter is D = f/N.
constexpr double lens_radius_from_f_stop(double focal_length, double f_stop) {
    return focal_length / (2 * f_stop);
}

}  // namespace glint
