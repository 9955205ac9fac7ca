// Fuzzy metal {type: fuzzy-metal, albedo, fuzz} (Ray Tracing in One Weekend's `metal`):
//   albedo  colour or texture in [0, 1], default 0.9: the fraction of light reflected;
//   fuzz    in [0, 1], default 0: the radius of the ball the mirror direction is perturbed by (0 is a
//           perfect mirror of reflectance albedo);
//   perturbation  ball (default) | sphere: a point in the ball or on its surface.
#include "glint/material/fuzzy_metal.hpp"

#include "glint/params/name_table.hpp"
#include "glint/params/params.hpp"
#include "glint/sampling/warps.hpp"

#include <cmath>

namespace glint {

std::optional<BsdfSample> FuzzyMetal::sample(const MaterialPoint& point, const Vec3& wo, Point2 u) const {
    if (wo.z == 0) {
        return std::nullopt;
    }
    Vec3 scattered = mirror_local(wo);
    if (fuzz_ > 0) {
        // A uniform direction, from the high bits of u.x and u.y.
        const Vec3 direction = square_to_uniform_sphere(u);
        double length = 1;  // on the sphere
        if (perturbation_ == Perturbation::Ball) {
            // Uniform in the ball: the distance from the centre has density 3ρ², so ρ = ξ^(1/3). The
            // interface hands a material two numbers, so ξ comes from the bits of u.x below its top 16,
            // which every sampler randomises independently of the top ones (jitter inside a stratum,
            // Owen scrambling, or plain random bits) for up to 65 536 samples per pixel.
            const double scaled = u.x * 65536.0;
            length = std::cbrt(scaled - std::floor(scaled));
        }
        scattered = normalize(scattered + (fuzz_ * length) * direction);
    }
    if (!same_hemisphere(wo, scattered)) {
        return std::nullopt;  // perturbed below the surface (the book's front-face normal): absorbed
    }
    return BsdfSample{scattered, point.specular / std::abs(scattered.z), 1.0, true, point.specular};
}

std::unique_ptr<Material> FuzzyMetal::create(Params& params, const BuildContext& context) {
    auto albedo = read_reflectance(params, "albedo", Rgb(0.9), context);
    const double fuzz = params.number("fuzz", 0.0);
    if (!(fuzz >= 0 && fuzz <= 1)) {
        params.fail("fuzz", "fuzzy-metal fuzz must lie in [0, 1] (the book clamps it to 1)");
    }
    static const EnumTable<FuzzyMetal::Perturbation> perturbations = {
        {"ball", FuzzyMetal::Perturbation::Ball}, {"sphere", FuzzyMetal::Perturbation::Sphere}};
    const FuzzyMetal::Perturbation perturbation =
        params.enumeration("perturbation", perturbations, FuzzyMetal::Perturbation::Ball);
    return std::make_unique<FuzzyMetal>(std::move(albedo), fuzz, perturbation);
}

}  // namespace glint
