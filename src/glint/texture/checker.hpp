#pragma once

#include <memory>

#include "glint/texture/texture.hpp"

namespace glint {

// Checkerboard of two textures: in 3-D (a solid checker of cubes, by hit.point) or on the surface's
// (u, v). `scale` is the number of checks per unit: per scene unit for `solid`, across [0, 1] of u
// and v for `uv`. The check containing the origin is `even`.
class CheckerTexture final : public Texture {
  public:
    enum class Space { Uv, Solid };
    CheckerTexture(std::shared_ptr<const Texture> even, std::shared_ptr<const Texture> odd, double scale,
                   Space space)
        : even_(std::move(even)), odd_(std::move(odd)), scale_(scale), space_(space) {}

    Rgb evaluate(const Hit& hit) const override;
    double min_value() const override { return std::min(even_->min_value(), odd_->min_value()); }
    double max_value() const override { return std::max(even_->max_value(), odd_->max_value()); }

    // {type: checker, scale, even, odd, space: uv | solid}
    static std::shared_ptr<const Texture> create(Params& params, const BuildContext& context);

  private:
    std::shared_ptr<const Texture> even_, odd_;
    double scale_;
    Space space_;
};

}  // namespace glint
