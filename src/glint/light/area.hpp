#pragma once

#include "glint/geometry/shape.hpp"
#include "glint/light/light.hpp"
#include "glint/material/material.hpp"

namespace glint {

class AreaEmitter;
class Rectangle;

// A light with area: a shape whose material emits (material.emitted() ≠ 0). Every object with an
// emitting material becomes one automatically, and {type: area, shape: {…}, radiance: L} adds such an
// object (see AreaEmitter). The radiance a light sample carries is material.emitted() at the sampled
// point, the very function a camera or BSDF ray that hits the shape sees, so light sampling and BSDF
// sampling estimate the same integral (what multiple importance sampling needs).
//
// Sampling: the shape chooses the point, as seen from the shading point (Shape::sample_seen_from):
// spheres seen from outside, also through a transform, by the cone of directions they subtend
// (uniform in solid angle, pbrt-v4 §6.2.4: no samples wasted on the far side); every other shape
// uniformly by area, converted to solid angle by distance² / |cos θ_light|. Soft shadows with umbra and
// penumbra follow.
class AreaLight final : public Light {
  public:
    AreaLight(const Shape& shape, const Material& material, int samples);
    std::optional<LightSample> sample(const Hit& at, Point2 u) const override;
    double pdf(const Hit& at, const Vec3& wi, const Hit* on_light) const override;
    int samples() const override { return samples_; }
    // The light sample of a point of the shape that another strategy chose (`seen`: the point, its
    // normal, the direction from the shading point and that strategy's density): what sample() returns
    // for the point the shape itself chooses.
    std::optional<LightSample> sample_of(const SeenSample& seen) const;
    const Shape& shape() const { return *shape_; }

    // {type: area, shape: {type: …, …}, radiance: L, scale: 1, two_sided: false, samples: 1}
    static std::unique_ptr<Light> create(Params& params, const BuildContext& context);

  private:
    const Shape* shape_;
    const Material* material_;
    int samples_;
    // The shape again when it is a Rectangle (else nullptr): a quad light with an AreaEmitter, as most
    // scenes' (the Cornell boxes'), is then sampled with no virtual call and no hit record, the same
    // arithmetic inline (issue 13: it was 7 % of the Cornell box's instructions).
    const Rectangle* rectangle_;
    // The material again when it is an AreaEmitter (else nullptr), whatever the shape: its radiance
    // needs only the normal, so sample_of builds no hit record for it (smallpt's sphere).
    const AreaEmitter* emitter_;
};

// The material of a {type: area} light's shape: black (it reflects nothing) and emitting L from its
// front side (the side its normal points to), or from both with two_sided.
class AreaEmitter final : public Material {
  public:
    AreaEmitter(const Rgb& radiance, bool two_sided) : radiance_(radiance), two_sided_(two_sided) {}
    Rgb emitted(const Hit& hit, const Vec3& wo) const override { return emitted_from(hit.normal, wo); }
    // emitted() of a point with geometric normal `normal`, which is all it reads.
    Rgb emitted_from(const Vec3& normal, const Vec3& wo) const {
        return two_sided_ || dot(normal, wo) > 0 ? radiance_ : Rgb{};
    }

  protected:
    Rgb evaluate(const MaterialPoint&, const Vec3&, const Vec3&) const override { return {}; }
    std::optional<BsdfSample> sample(const MaterialPoint&, const Vec3&, Point2) const override {
        return std::nullopt;
    }
    double pdf(const MaterialPoint&, const Vec3&, const Vec3&) const override { return 0; }

  private:
    Rgb radiance_;
    bool two_sided_;
};

// Whether a material emits light, so that an object made of it is an area light: asked of a front
// face seen head-on, where every emitter (one- or two-sided) shines.
bool emits_light(const Material& material);

}  // namespace glint
