#include "glint/light/ambient.hpp"

#include "glint/params/params.hpp"

namespace glint {

std::unique_ptr<Light> AmbientLight::create(Params& params, const BuildContext&) {
    return std::make_unique<AmbientLight>(params.non_negative_color("radiance", Rgb(0.1)) *
                                          params.non_negative("scale", 1.0));
}

}  // namespace glint
