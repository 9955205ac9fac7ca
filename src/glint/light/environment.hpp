#pragma once

#include <memory>

#include "glint/image/image.hpp"
#include "glint/light/light.hpp"
#include "glint/sampling/distribution.hpp"

namespace glint {

// Environment light {type: environment}: radiance arriving from infinitely far away in every
// direction, which rays that escape the scene see (it replaces `background`). One of:
//   radiance: [r, g, b]                                    a constant sky;
//   radiance: {type: gradient, bottom: c0, top: c1}       Ray Tracing in One Weekend's sky: the colour
//                                                          lerp(0.5 (dir.y + 1), bottom, top);
//   image: sky.exr | sky.pfm (rotation: degrees about +y)  an equirectangular (latitude–longitude) map:
//       the pixel column u = 0.5 + atan2(dir.x, −dir.z) / 2π, row v = acos(dir.y) / π; so the image
//       centre lies along −z, the top row at +y. Nearest pixel (the map is piecewise constant).
// and `scale` (default 1) multiplies it.
//
// Sampling: constant and gradient skies uniformly over the sphere (for the direct-lighting integrators:
// the path tracer leaves them to BSDF sampling, which matches their smooth radiance better); images by a 2-D
// piecewise-constant distribution over (u, v) of pixel luminance · sin θ (marginal over rows, conditional per
// row), whose density per unit (u, v) becomes the solid-angle density pdf(u, v) / (2π² sin θ).
class EnvironmentLight final : public Light {
  public:
    // Constant (bottom == top) or gradient sky.
    EnvironmentLight(const Rgb& bottom, const Rgb& top);
    // Image sky; `image` in linear radiance, already scaled.
    EnvironmentLight(Image image, double rotation_degrees);

    std::optional<LightSample> sample(const Hit& at, Point2 u) const override;
    double pdf(const Hit& at, const Vec3& wi, const Hit* on_light) const override;
    Rgb escaped(const Vec3& dir) const override;
    bool is_environment() const override { return true; }
    // A constant or gradient sky: cosine-weighted BSDF sampling already follows it closely.
    bool worth_sampling_in_paths() const override { return distribution_ != nullptr; }

    static std::unique_ptr<Light> create(Params& params, const BuildContext& context);

    // The map's (u, v) ↔ direction convention (the rotation is applied outside).
    static Point2 direction_to_uv(const Vec3& dir);
    static Vec3 uv_to_direction(Point2 uv);

  private:
    Vec3 to_map(const Vec3& world) const;    // world direction → the map's frame (undo rotation)
    Vec3 from_map(const Vec3& local) const;  // and back

    Rgb bottom_, top_;
    Image image_;  // empty for constant and gradient skies
    std::unique_ptr<Distribution2D> distribution_;
    double cos_rotation_ = 1, sin_rotation_ = 0;
};

}  // namespace glint
