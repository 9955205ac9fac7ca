#include "glint/sampling/pixel_filter.hpp"

#include <algorithm>
#include <cmath>

#include "glint/sampling/low_discrepancy.hpp"

namespace glint {

namespace {

// One axis of a tent filter with `subpixels` sub-pixels: the leading part of u picks the sub-pixel,
// the rest, rescaled to [0,1), is warped by the tent about that sub-pixel's centre.
double tent_axis(double u, double radius, int subpixels) {
    const double scaled = u * subpixels;
    const double cell = std::min(std::floor(scaled), subpixels - 1.0);
    // u·s − ⌊u·s⌋ can round up to 1 when s is not a power of two.
    const double v = std::min(scaled - cell, kOneMinusEpsilon);
    return (cell + 0.5) / subpixels + radius * tent_inverse_cdf(v);
}

}  // namespace

const EnumTable<PixelFilterType>& pixel_filter_types() {
    static const EnumTable<PixelFilterType> table = {
        {"box", PixelFilterType::box},
        {"tent", PixelFilterType::tent},
    };
    return table;
}

double tent_inverse_cdf(double v) {
    return v < 0.5 ? std::sqrt(2 * v) - 1 : 1 - std::sqrt(2 - 2 * v);
}

Point2 PixelFilter::offset(Point2 u) const {
    switch (type) {
        case PixelFilterType::box:
            return u;
        case PixelFilterType::tent:
            return {tent_axis(u.x, radius, subpixels), tent_axis(u.y, radius, subpixels)};
    }
    return u;
}

PixelFilter read_pixel_filter(Params& params) {
    PixelFilter filter;
    filter.type = params.enumeration("type", pixel_filter_types());
    if (filter.type == PixelFilterType::tent) {
        filter.radius = params.positive("radius", filter.radius);
        const std::int64_t subpixels = params.positive_integer("subpixels", filter.subpixels);
        if (subpixels > kMaxSubpixels) {
            params.fail("subpixels", params.what() + ".subpixels is more than " +
                                         std::to_string(kMaxSubpixels) +
                                         " a side (each sub-pixel takes bits of the sample from its tent)");
        }
        filter.subpixels = static_cast<int>(subpixels);
    }
    return filter;
}

}  // namespace glint
