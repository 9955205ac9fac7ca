// Fuzzy metal {type: fuzzy-metal, albedo, fuzz} (Ray Tracing in One Weekend's `metal`):
//   albedo  colour or texture in [0, 1], default 0.9: the fraction of light reflected;
//   fuzz    in [0, 1], default 0: the radius of the sphere the mirror direction is perturbed by (0 is a
//           perfect mirror of reflectance albedo).
#include "glint/material/fuzzy_metal.hpp"

#include "glint/params/params.hpp"

namespace glint {

std::optional<BsdfSample> FuzzyMetal::sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const {
    if (wo.z == 0) {
        return std::nullopt;
    }
    Vec3 scattered = mirror_local(wo);
    if (fuzz_ > 0) {
        // A uniform point on the unit sphere (the book's random_unit_vector): z uniform in [−1, 1].
        const double z = 1 - 2 * u.x;
        const double r = safe_sqrt(1 - z * z);
        const SinCos phi = sincos_turns(u.y);
        scattered = normalize(scattered + fuzz_ * Vec3{r * phi.cos, r * phi.sin, z});
    }
    if (!same_hemisphere(wo, scattered)) {
        return std::nullopt;  // perturbed below the surface (the book's front-face normal): absorbed
    }
    return BsdfSample{scattered, point.specular / std::abs(scattered.z), 1.0, true};
}

std::unique_ptr<Material> FuzzyMetal::create(Params& params, const BuildContext& context) {
    auto albedo = read_reflectance(params, "albedo", Rgb(0.9), context);
    const double fuzz = params.number("fuzz", 0.0);
    if (!(fuzz >= 0 && fuzz <= 1)) {
        params.fail("fuzz", "fuzzy-metal fuzz must lie in [0, 1] (the book clamps it to 1)");
    }
    return std::make_unique<FuzzyMetal>(std::move(albedo), fuzz);
}

}  // namespace glint
