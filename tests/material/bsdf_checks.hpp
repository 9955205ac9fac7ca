// Statistical checks shared by the material tests: a χ² test of a BSDF's sampling against its pdf,
// and a Monte Carlo estimate of its reflected energy. Deterministic: the numbers come from hashes.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "glint/core/frame.hpp"
#include "glint/core/hash.hpp"
#include "glint/material/material.hpp"

namespace glint::testing {

// A hit at the origin with a tilted normal (no axis-aligned special cases), uv (0.25, 0.75).
inline Hit test_hit(const Vec3& normal = normalize(Vec3{0.3, -0.2, 1.0})) {
    Hit hit;
    hit.t = 1;
    hit.point = Vec3{0, 0, 0};
    hit.normal = hit.shading_normal = normal;
    hit.uv = {0.25, 0.75};
    return hit;
}

// A direction at cos θ = `cos_theta` from the hit's normal (negative: below the surface), azimuth φ.
inline Vec3 direction_at(const Hit& hit, double cos_theta, double phi) {
    const double s = safe_sqrt(1 - cos_theta * cos_theta);
    return Frame::from_normal(hit.shading_normal).to_world({s * std::cos(phi), s * std::sin(phi), cos_theta});
}

// The mirror direction of wo about the hit's shading normal, in world space as the paper writes it
// (eq. 16, R = 2(wo·N)N − wo): a reference independent of the shading frame.
inline Vec3 mirror_direction(const Hit& hit, const Vec3& wo) {
    return 2 * dot(wo, hit.shading_normal) * hit.shading_normal - wo;
}

inline Point2 test_point(std::uint64_t seed, std::uint32_t i) {
    const SampleKey key{seed, i, 0, 0};
    return {key.uniform(0), key.uniform(1)};
}

struct Chi2Outcome {
    double statistic = 0;
    int degrees_of_freedom = 0;
    double critical = 0;      // at the test's significance
    bool impossible = false;  // a sample fell where the pdf integrates to zero
    std::string report;
};

// Upper critical value of χ² with k degrees of freedom at the standard normal quantile z, by the
// Wilson–Hilferty cube approximation (accurate to a fraction of a percent for k ≥ 10).
inline double chi2_critical(int k, double z) {
    const double a = 2.0 / (9.0 * k);
    return k * std::pow(1 - a + z * std::sqrt(a), 3);
}

// Bins the directions sample() returns in (cos θ, φ) about the shading normal over the whole sphere,
// integrates pdf() over each bin (midpoint rule on a sub-grid: dω = d cos θ dφ), pools the bins whose
// expected count is below 5, and adds one bin for samples that are not in the pdf (delta lobes and
// failed samples), expected N (1 − ∫pdf). Significance 10⁻³ (z = 3.09).
inline Chi2Outcome chi2_test(const Material& material, const Hit& hit, const Vec3& wo, int samples,
                             std::uint64_t seed) {
    constexpr int kCos = 20, kPhi = 40, kSub = 12;
    const Bsdf bsdf = material.bsdf(hit);
    const Frame frame = Frame::from_normal(hit.shading_normal);
    std::vector<double> observed(kCos * kPhi, 0), expected(kCos * kPhi, 0);
    double other_observed = 0;
    for (int i = 0; i < samples; ++i) {
        const auto s = bsdf.sample(wo, test_point(seed, static_cast<std::uint32_t>(i)));
        if (!s || s->delta) {
            ++other_observed;
            continue;
        }
        const Vec3 l = frame.to_local(s->wi);
        const int ci = std::clamp(static_cast<int>((l.z + 1) / 2 * kCos), 0, kCos - 1);
        double phi = std::atan2(l.y, l.x);
        if (phi < 0) {
            phi += 2 * kPi;
        }
        const int pi = std::clamp(static_cast<int>(phi / (2 * kPi) * kPhi), 0, kPhi - 1);
        ++observed[ci * kPhi + pi];
    }
    const double dc = 2.0 / kCos / kSub, dp = 2 * kPi / kPhi / kSub;
    double integral = 0;
    for (int ci = 0; ci < kCos; ++ci) {
        for (int pi = 0; pi < kPhi; ++pi) {
            double sum = 0;
            for (int a = 0; a < kSub; ++a) {
                for (int b = 0; b < kSub; ++b) {
                    const double c = -1 + (ci * kSub + a + 0.5) * dc;
                    const double p = (pi * kSub + b + 0.5) * dp;
                    const double sin_theta = safe_sqrt(1 - c * c);
                    const Vec3 local{sin_theta * std::cos(p), sin_theta * std::sin(p), c};
                    sum += bsdf.pdf(wo, frame.to_world(local));
                }
            }
            expected[ci * kPhi + pi] = sum * dc * dp * samples;
            integral += sum * dc * dp;
        }
    }
    observed.push_back(other_observed);
    expected.push_back(std::max(0.0, 1 - integral) * samples);

    Chi2Outcome out;
    double pooled_observed = 0, pooled_expected = 0;
    int bins = 0;
    for (size_t i = 0; i < observed.size(); ++i) {
        if (expected[i] < 5) {
            pooled_observed += observed[i];
            pooled_expected += expected[i];
            continue;
        }
        out.statistic += sqr(observed[i] - expected[i]) / expected[i];
        ++bins;
    }
    if (pooled_expected >= 5) {
        out.statistic += sqr(pooled_observed - pooled_expected) / pooled_expected;
        ++bins;
    } else if (pooled_observed > 2 * pooled_expected + 10) {
        out.impossible = true;  // many samples where the pdf says there are almost none
    }
    out.degrees_of_freedom = bins - 1;
    out.critical = chi2_critical(out.degrees_of_freedom, 3.09);
    std::ostringstream report;
    report << "chi2 = " << out.statistic << " with " << out.degrees_of_freedom << " dof (critical "
           << out.critical << "), pdf integral " << integral << ", samples outside the pdf " << other_observed
           << ", pooled observed " << pooled_observed << " expected " << pooled_expected;
    out.report = report.str();
    return out;
}

// Monte Carlo estimate of the directional albedo ∫ f(wo, wi) |cos θi| dωi (the path weight's mean)
// in the luminance of the weights, and its standard error.
struct AlbedoEstimate {
    double mean = 0;
    double standard_error = 0;
};
inline AlbedoEstimate estimate_albedo(const Material& material, const Hit& hit, const Vec3& wo, int samples,
                                      std::uint64_t seed) {
    const Bsdf bsdf = material.bsdf(hit);
    double sum = 0, sum2 = 0;
    for (int i = 0; i < samples; ++i) {
        const auto s = bsdf.sample(wo, test_point(seed, static_cast<std::uint32_t>(i)));
        double w = 0;
        if (s && s->pdf > 0) {
            w = (s->f * (std::abs(dot(hit.shading_normal, s->wi)) / s->pdf)).luminance();
        }
        sum += w;
        sum2 += w * w;
    }
    AlbedoEstimate e;
    e.mean = sum / samples;
    e.standard_error = std::sqrt(std::max(0.0, sum2 / samples - e.mean * e.mean) / samples);
    return e;
}

}  // namespace glint::testing
