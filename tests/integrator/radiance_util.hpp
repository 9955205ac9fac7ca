// Helpers for the light and integrator tests: scenes from YAML text, renders into a film, means of
// pixel regions with their standard error, and a χ² goodness-of-fit test.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "glint/image/film.hpp"
#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"

namespace glint::test {

inline Scene scene_from_yaml(const std::string& yaml, const RenderFlags& overrides = {}) {
    return build_scene(parse_scene_text(yaml, "test.yaml", "."), overrides);
}

inline Film render_film(const Scene& scene) {
    Film film(scene.view.settings.width, scene.view.settings.height);
    const RenderStats stats = render(scene, film);
    EXPECT_EQ(stats.nonfinite_samples, 0u);
    return film;
}

// The mean of one channel (or the luminance, channel −1) over pixels [x0, x1) × [y0, y1), and its
// standard error estimated from the spread of the pixel values (each pixel an independent estimate).
struct RegionMean {
    double mean = 0;
    double standard_error = 0;
};

inline RegionMean region_mean(const Film& film, int x0, int y0, int x1, int y1, int channel = -1) {
    std::vector<double> values;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            const Rgb p = film.pixel(x, y);
            values.push_back(channel < 0 ? (p.r + p.g + p.b) / 3 : p[channel]);
        }
    }
    double sum = 0;
    for (double v : values) {
        sum += v;
    }
    const double n = static_cast<double>(values.size());
    const double mean = sum / n;
    double squares = 0;
    for (double v : values) {
        squares += (v - mean) * (v - mean);
    }
    return {mean, std::sqrt(squares / (n - 1) / n)};
}

// Pearson's χ² test of observed counts against expected counts, merging cells with fewer than 5
// expected into one (Nori's and Mitsuba's warp tests do the same). Returns the p-value, from the
// Wilson–Hilferty normal approximation of the χ² distribution.
inline double chi2_p_value(const std::vector<double>& observed, const std::vector<double>& expected) {
    double chi2 = 0;
    int cells = 0;
    double pooled_observed = 0;
    double pooled_expected = 0;
    for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < 5) {
            pooled_observed += observed[i];
            pooled_expected += expected[i];
            continue;
        }
        chi2 += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
        ++cells;
    }
    if (pooled_expected >= 5) {
        chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
        ++cells;
    } else if (pooled_observed > 10) {
        return 0;  // many samples where the density says (almost) none belong
    }
    const double k = cells - 1;
    const double z = (std::cbrt(chi2 / k) - (1 - 2 / (9 * k))) / std::sqrt(2 / (9 * k));
    return 0.5 * std::erfc(z / std::sqrt(2.0));
}

}  // namespace glint::test
