// Cameras (paper §IV): turn a point on the film (and one on the lens) into a primary ray.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "glint/core/ray.hpp"
#include "glint/params/name_table.hpp"

namespace glint {

class Params;
struct BuildContext;

class Camera {
  public:
    virtual ~Camera() = default;
    // `film` is in pixels: x right from the left edge, y down from the top edge, pixel (i, j) covering
    // [i, i+1) × [j, j+1). `lens` is a point of the unit square, for cameras with an aperture.
    // A film point the camera sees nothing through (outside a fisheye's image circle) gets a ray
    // whose direction is the zero vector: see sees_scene().
    virtual Ray generate_ray(Point2 film, Point2 lens) const = 0;
    // generate_ray of several points at once: rays[i] = generate_ray(film[i], lens[i]), bit for bit (the
    // spans are of one size). The render loop asks for a batch's rays together (up to 16, of one pixel or of
    // several); a camera that makes them faster together (the thin lens, four at a time in AVX2 lanes)
    // overrides it.
    virtual void generate_rays(std::span<const Point2> film, std::span<const Point2> lens,
                               std::span<Ray> rays) const;
    // Whether generate_ray reads `lens`. The renderer draws no lens sample for a camera that does not
    // (a sample_2d is ~160 instructions; the other dimensions are numbered apart, so they keep their
    // values).
    virtual bool uses_lens() const { return true; }
};

// Whether a camera ray looks into the scene. Every real camera ray has a unit direction, so the zero
// direction is free to mean "no ray here"; the renderer records black for it without tracing. (Why
// not std::optional<Ray>: it would change the interface every camera and caller already uses, for the
// one camera that needs it; a zero direction costs one compare in render_sample.)
constexpr bool sees_scene(const Ray& camera_ray) {
    return camera_ray.direction != Vec3{};
}

// The orthonormal viewing basis of paper §IV as corrected in the errata:
// w = (eye − look_at)/‖eye − look_at‖, u = (up × w)/‖up × w‖, v = w × u.
struct CameraBasis {
    Vec3 u, v, w;
    bool up_was_degenerate = false;  // up ∥ w: another up was chosen (see camera_basis)
};
// When up is parallel to w (looking straight along it) the cross product vanishes. The basis then
// uses up = −z when looking down and +z when looking up (the roll a camera tilted from a level view
// would have), and +y for other degenerate cases. Never NaN.
// Precondition: eye ≠ look_at and up ≠ 0.
CameraBasis camera_basis(const Vec3& eye, const Vec3& look_at, const Vec3& up);

// The image size a camera is built for.
struct FilmSize {
    int width = 0;
    int height = 0;
};

using CameraFactory = std::function<std::unique_ptr<Camera>(Params&, const BuildContext&, FilmSize)>;
struct CameraEntry {
    std::string name;
    CameraFactory create;
};
// The name → constructor table of cameras ("pinhole", …).
const NameTable<CameraEntry>& camera_table();

// Where a camera stands and how it is turned: eye, look_at and up (read and checked), and the basis.
// Shared by every camera.
struct ViewFrame {
    Vec3 eye;
    Vec3 look_at;
    CameraBasis basis;
};
ViewFrame read_view_frame(Params& params);

// Where a camera with a near distance starts its rays: on the plane across the view direction at that
// distance (what a user expects of a near clipping plane), or at that distance along each ray from
// where it leaves the eye or lens (a sphere about the eye: smallpt's camera as g++ compiles it).
enum class NearShape { Plane, Sphere };

// The viewing parameters shared by the perspective cameras: eye, look_at, up, either the paper's
// view-plane distance d (in pixels) with zoom or a vertical field of view, and the near clipping
// surface. Reads and checks them.
struct ViewParams {
    Vec3 eye;
    Vec3 look_at;
    CameraBasis basis;
    double view_distance = 0;  // d, in pixel units
    double pixel_size = 1;     // 1 / zoom
    double near = 0;           // the near surface's distance from the eye (see NearShape); 0: none
    NearShape near_shape = NearShape::Plane;
};
ViewParams read_view_params(Params& params, FilmSize film);
// The (not normalised) direction from the eye through the view-plane point of `film`: its component
// along −w is the view distance d, across it the film offset from the image centre in view-plane units.
// Inline, as ray_from_near_surface: both are on every camera ray's path (inlined, RTIOW's final scene
// runs 0.8 % fewer instructions). The thin lens repeats both in AVX2 lanes, operation for operation
// (thin_lens.cpp, thin_lens_rays_avx2): change them together.
inline Vec3 view_plane_direction(const ViewParams& view, FilmSize size, Point2 film) {
    const double x = view.pixel_size * (film.x - 0.5 * size.width);
    const double y = view.pixel_size * (0.5 * size.height - film.y);
    const CameraBasis& b = view.basis;
    return x * b.u + y * b.v - view.view_distance * b.w;
}
// The primary ray from `origin` (a point of the plane through the eye across w: the eye or a lens point)
// along `direction`, whose component along the view direction −w is `forward` (> 0), started where it
// crosses the view's near surface, so that nothing nearer is seen. The returned direction is unit; with
// near = 0 the ray is {origin, normalize(direction)}, bit for bit.
inline Ray ray_from_near_surface(const ViewParams& view, const Vec3& origin, const Vec3& direction,
                                 double forward) {
    const Vec3 unit = normalize(direction);
    if (view.near == 0) {
        return {origin, unit};  // no near surface: today's rays, unchanged
    }
    if (view.near_shape == NearShape::Sphere) {
        return {origin + view.near * unit, unit};
    }
    // `direction` advances `forward` along the view per unit of t: scaling it by near / forward reaches
    // the plane exactly, without the rounding of a cosine taken from the normalised direction.
    return {origin + direction * (view.near / forward), unit};
}

}  // namespace glint
