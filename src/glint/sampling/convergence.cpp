#include "glint/sampling/convergence.hpp"

#include <cmath>

#include "glint/sampling/sampler.hpp"

namespace glint {

TestIntegrand edge_integrand() {
    const double slope = (std::sqrt(5.0) - 1) / 2, offset = 0.2;
    // The line runs from (0, 0.2) to (1, 0.818): it crosses only the vertical sides, so the area below
    // it is the trapezoid c + m/2.
    return {"edge", [=](Point2 p) { return p.y < offset + slope * p.x ? 1.0 : 0.0; }, offset + slope / 2};
}

TestIntegrand smooth_integrand() {
    constexpr double sigma = 0.25, mx = 0.4, my = 0.55;
    // ∫₀¹ exp(−(t−μ)²/(2σ²)) dt = σ√(π/2) (erf((1−μ)/(σ√2)) + erf(μ/(σ√2))).
    auto axis = [](double mu) {
        const double s = sigma * std::sqrt(2.0);
        return sigma * std::sqrt(M_PI / 2) * (std::erf((1 - mu) / s) + std::erf(mu / s));
    };
    return {"smooth",
            [=](Point2 p) {
                const double dx = p.x - mx, dy = p.y - my;
                return std::exp(-(dx * dx + dy * dy) / (2 * sigma * sigma));
            },
            axis(mx) * axis(my)};
}

double log_log_slope(const std::vector<std::uint32_t>& x, const std::vector<double>& y,
                     std::uint32_t fit_from) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int count = 0;
    for (size_t i = 0; i < x.size(); ++i) {
        if (x[i] < fit_from || !(y[i] > 0)) {
            continue;
        }
        const double lx = std::log(static_cast<double>(x[i])), ly = std::log(y[i]);
        sx += lx, sy += ly, sxx += lx * lx, sxy += lx * ly, ++count;
    }
    const double denominator = count * sxx - sx * sx;
    return count >= 2 && denominator > 0 ? (count * sxy - sx * sy) / denominator : 0.0;
}

std::vector<ConvergenceCurve> convergence_study(const std::vector<std::string>& patterns,
                                                const std::vector<TestIntegrand>& integrands,
                                                const std::vector<std::uint32_t>& counts,
                                                std::uint32_t pixels, std::uint64_t seed,
                                                std::uint32_t fit_from) {
    std::vector<ConvergenceCurve> curves;
    for (const std::string& pattern : patterns) {
        const size_t first = curves.size();
        for (const TestIntegrand& integrand : integrands) {
            curves.push_back({pattern, integrand.name, {}, {}, 0});
        }
        for (std::uint32_t requested : counts) {
            const auto sampler = make_sampler(pattern, requested);
            if (!sampler) {
                return {};
            }
            const std::uint32_t n = sampler->samples_per_pixel();
            std::vector<double> squared_error(integrands.size(), 0.0);
            for (std::uint32_t px = 0; px < pixels; ++px) {
                std::vector<double> sum(integrands.size(), 0.0);
                SampleKey key{seed, px, 0, 0};
                for (key.sample = 0; key.sample < n; ++key.sample) {
                    const Point2 p = sampler->sample_2d(key, kFilmDimension);
                    for (size_t k = 0; k < integrands.size(); ++k) {
                        sum[k] += integrands[k].f(p);
                    }
                }
                for (size_t k = 0; k < integrands.size(); ++k) {
                    const double error = sum[k] / n - integrands[k].integral;
                    squared_error[k] += error * error;
                }
            }
            for (size_t k = 0; k < integrands.size(); ++k) {
                curves[first + k].samples.push_back(n);
                curves[first + k].rmse.push_back(std::sqrt(squared_error[k] / pixels));
            }
        }
        for (size_t k = first; k < curves.size(); ++k) {
            curves[k].slope = log_log_slope(curves[k].samples, curves[k].rmse, fit_from);
        }
    }
    return curves;
}

}  // namespace glint
