// Dielectric {type: dielectric, ior, absorption, fresnel}:
//   ior         refractive index inside, > 0 (≠ 1 for a visible interface), default 1.5 (glass; water
//               1.333, diamond 2.417); the outside is 1;
//   absorption  σ per scene unit, colour ≥ 0, default 0: light travelling d inside keeps exp(−σ d);
//   fresnel     exact (default) | schlick | schlick-outside: the reflect/refract probability F is the
//               exact dielectric Fresnel reflectance, or Schlick's approximation as Ray Tracing in One
//               Weekend computes it (schlick) or as smallpt does (schlick-outside).
#include "glint/material/dielectric.hpp"

#include "glint/material/fresnel.hpp"
#include "glint/params/name_table.hpp"

namespace glint {

std::optional<BsdfSample> Dielectric::sample(const MaterialPoint&, const Vec3& wo, Point2 u) const {
    if (wo.z == 0) {
        return std::nullopt;
    }
    const bool outside = wo.z > 0;           // wo on the side the normal points to
    const double n1 = outside ? 1.0 : ior_;  // index on wo's side
    const double n2 = outside ? ior_ : 1.0;  // index on the other side
    const Vec3 n{0, 0, outside ? 1.0 : -1.0};
    const double c1 = std::abs(wo.z);
    const std::optional<Vec3> refracted = refract(-wo, n, n1, n2);
    double reflectance = 1;  // total internal reflection
    if (refracted) {
        switch (fresnel_) {
            case Fresnel::Exact:
                reflectance = fresnel_dielectric(c1, n1, n2);
                break;
            case Fresnel::Schlick:
                reflectance = schlick(c1, fresnel_r0(n1, n2));
                break;
            case Fresnel::SchlickOutside: {
                const double cos_outside = outside ? c1 : std::abs(normalize(*refracted).z);
                reflectance = schlick(cos_outside, fresnel_r0(n1, n2));
                break;
            }
        }
    }
    if (u.x < reflectance) {
        // Weight (R / cos) · cos / R = 1.
        return BsdfSample{mirror_local(wo), Rgb(reflectance / c1), reflectance, true, Rgb(1.0)};
    }
    const Vec3 wi = normalize(*refracted);
    const double cos_i = std::abs(wi.z);
    if (cos_i <= 0) {
        return std::nullopt;
    }
    const double transmittance = 1 - reflectance;
    return BsdfSample{wi, Rgb(transmittance * sqr(n1 / n2) / cos_i), transmittance, true, Rgb(sqr(n1 / n2))};
}

std::unique_ptr<Material> Dielectric::create(Params& params, const BuildContext&) {
    const double ior = params.positive("ior", 1.5);
    if (ior > 10) {
        params.fail("ior", "dielectric ior must be at most 10 (glass 1.5, water 1.333, diamond 2.417)");
    }
    const Rgb absorption = params.non_negative_color("absorption", Rgb());
    static const EnumTable<Fresnel> fresnel_rules = {{"exact", Fresnel::Exact},
                                                     {"schlick", Fresnel::Schlick},
                                                     {"schlick-outside", Fresnel::SchlickOutside}};
    const Fresnel fresnel = params.enumeration("fresnel", fresnel_rules, Fresnel::Exact);
    return std::make_unique<Dielectric>(ior, absorption, fresnel);
}

}  // namespace glint
