// Emissive {type: emissive, radiance, scale, two_sided}:
//   radiance   colour or texture ≥ 0, default 1;
//   scale      ≥ 0, default 1 (a brightness multiplier);
//   two_sided  default false: emit only to the side of the outward normal.
#include "glint/material/emissive.hpp"

#include "glint/params/params.hpp"

namespace glint {

Rgb Emissive::emitted(const Hit& hit, const Vec3& wo) const {
    if (!two_sided_ && dot(hit.normal, wo) <= 0) {
        return {};
    }
    return radiance_->evaluate(hit) * scale_;
}

std::unique_ptr<Material> Emissive::create(Params& params, const BuildContext& context) {
    auto radiance = read_texture(params, "radiance", Rgb(1.0), context);
    const double scale = params.non_negative("scale", 1.0);
    const bool two_sided = params.boolean("two_sided", false);
    return std::make_unique<Emissive>(std::move(radiance), scale, two_sided);
}

}  // namespace glint
