// Checker {type: checker, scale, even, odd, space}:
//   space  `uv` (default) or `solid`;
//   scale  checks per unit (> 0): default 10 for uv (10 × 10 checks over the surface), 1 for solid;
//   even, odd  colours or textures, default 0.8 and 0.2.
#include "glint/texture/checker.hpp"

#include <cmath>

#include "glint/params/name_table.hpp"

namespace glint {

namespace {
// Parity (0 or 1) of the cell index along one axis, computed in floating point: converting the index to
// an integer would overflow far out on an infinite plane (beyond 2⁶³), and beyond 2⁵³ every double is an
// even integer anyway. The 1e-9 shift keeps surfaces that lie exactly on a cell boundary (the floor
// y = 0 under a solid checker) in one cell, instead of speckled by the sign of rounding errors.
int cell_parity(double x) {
    const double cell = std::floor(x + 1e-9);
    return cell - 2 * std::floor(cell / 2) == 1 ? 1 : 0;
}
}  // namespace

Rgb CheckerTexture::evaluate(const Hit& hit) const {
    int parity = 0;
    if (space_ == Space::Uv) {
        const Point2 uv = surface_uv(hit);
        parity = cell_parity(uv.x * scale_) ^ cell_parity(uv.y * scale_);
    } else {
        parity = cell_parity(hit.point.x * scale_) ^ cell_parity(hit.point.y * scale_) ^
                 cell_parity(hit.point.z * scale_);
    }
    return parity == 0 ? even_->evaluate(hit) : odd_->evaluate(hit);
}

std::shared_ptr<const Texture> CheckerTexture::create(Params& params, const BuildContext& context) {
    static const EnumTable<Space> spaces = {{"uv", Space::Uv}, {"solid", Space::Solid}};
    const Space space = params.enumeration("space", spaces, Space::Uv);
    const double scale = params.positive("scale", space == Space::Uv ? 10.0 : 1.0);
    auto even = read_texture(params, "even", Rgb(0.8), context);
    auto odd = read_texture(params, "odd", Rgb(0.2), context);
    return std::make_shared<CheckerTexture>(std::move(even), std::move(odd), scale, space);
}

}  // namespace glint
