#include "glint/import/pbrt_spectra.hpp"

#include <algorithm>
#include <cmath>

namespace glint::pbrt_spectra {
namespace {

// Measured η and κ of the metals pbrt-v4 names, interpolated at kRgbWavelengths (630, 532, 465 nm)
// from the tabulated data pbrt-v4 ships (util/spectrum.cpp; the sources are the usual handbooks of
// optical constants). MgO and TiO2 are dielectrics there: κ = 0.
struct NamedMetal {
    const char* name;
    ComplexIor ior;
};
const NamedMetal kMetals[] = {
    {"Ag", {{0.1342, 0.1297, 0.1395}, {3.9628, 3.1942, 2.6135}}},
    {"Al", {{1.3571, 0.8843, 0.6605}, {7.5878, 6.4700, 5.6536}}},
    {"Au", {{0.1837, 0.4573, 1.3724}, {3.0663, 2.4084, 1.8250}}},
    {"Cu", {{0.2459, 1.0723, 1.1569}, {3.3784, 2.5907, 2.4572}}},
    {"CuZn", {{0.4450, 0.5682, 0.9470}, {3.5220, 2.5880, 1.9200}}},
    {"MgO", {{1.7348, 1.7422, 1.7502}, {0, 0, 0}}},
    {"TiO2", {{2.8750, 2.9685, 3.1176}, {0, 0, 0}}},
};

// The Schott glasses pbrt-v4 names, at 550 nm (the same tables).
struct NamedGlass {
    const char* name;
    double ior;
};
const NamedGlass kGlasses[] = {
    {"glass-BK7", 1.5185}, {"glass-BAF10", 1.6731}, {"glass-FK51A", 1.4878}, {"glass-LASF9", 1.8558},
    {"glass-F5", 1.6771},  {"glass-F10", 1.7336},   {"glass-F11", 1.7911},
};

// The CIE 1931 colour-matching functions by the multi-lobe Gaussian fit of Wyman, Sloan and Shirley,
// "Simple Analytic Approximations to the CIE XYZ Color Matching Functions" (JCGT 2013): a lobe is
// exp(−½ (τ (λ − μ))²) with τ = τ₁ below the peak μ and τ₂ above.
double lobe(double lambda, double mu, double tau_below, double tau_above) {
    const double t = (lambda - mu) * (lambda < mu ? tau_below : tau_above);
    return std::exp(-0.5 * t * t);
}
double cie_x(double l) {
    return 1.056 * lobe(l, 599.8, 0.0264, 0.0323) + 0.362 * lobe(l, 442.0, 0.0624, 0.0374) -
           0.065 * lobe(l, 501.1, 0.0490, 0.0382);
}
double cie_y(double l) {
    return 0.821 * lobe(l, 568.8, 0.0213, 0.0247) + 0.286 * lobe(l, 530.9, 0.0613, 0.0322);
}
double cie_z(double l) {
    return 1.217 * lobe(l, 437.0, 0.0845, 0.0278) + 0.681 * lobe(l, 459.0, 0.0385, 0.0725);
}

// CIE XYZ to linear sRGB (D65 white).
Rgb xyz_to_rgb(double x, double y, double z) {
    return {3.2404542 * x - 1.5371385 * y - 0.4985314 * z, -0.9692660 * x + 1.8760108 * y + 0.0415560 * z,
            0.0556434 * x - 0.2040259 * y + 1.0572252 * z};
}

// ∫ cmf · spectrum over the visible range, 1 nm steps; the result's luminance is ∫ ȳ · spectrum.
template <typename Spectrum>
Rgb integrate_rgb(const Spectrum& spectrum, double* luminance) {
    double x = 0, y = 0, z = 0;
    for (double lambda = 360; lambda <= 830; lambda += 1) {
        const double s = spectrum(lambda);
        x += cie_x(lambda) * s;
        y += cie_y(lambda) * s;
        z += cie_z(lambda) * s;
    }
    *luminance = y;
    return xyz_to_rgb(x, y, z);
}

// A piecewise-linear function through (λ, value) pairs, constant beyond its ends.
double interpolate(const std::vector<double>& pairs, double lambda) {
    const std::size_t n = pairs.size() / 2;
    if (n == 0) {
        return 0;
    }
    if (lambda <= pairs[0]) {
        return pairs[1];
    }
    for (std::size_t i = 1; i < n; ++i) {
        const double l0 = pairs[2 * i - 2], l1 = pairs[2 * i];
        if (lambda <= l1) {
            const double t = l1 > l0 ? (lambda - l0) / (l1 - l0) : 1;
            return pairs[2 * i - 1] + t * (pairs[2 * i + 1] - pairs[2 * i - 1]);
        }
    }
    return pairs[2 * n - 1];
}

double normal_incidence(double eta, double k) {
    return ((eta - 1) * (eta - 1) + k * k) / ((eta + 1) * (eta + 1) + k * k);
}

}  // namespace

std::optional<ComplexIor> named_metal(const std::string& metal) {
    for (const NamedMetal& m : kMetals) {
        if (metal == m.name) {
            return m.ior;
        }
    }
    return std::nullopt;
}

std::optional<double> named_glass_ior(const std::string& name) {
    for (const NamedGlass& g : kGlasses) {
        if (name == g.name) {
            return g.ior;
        }
    }
    return std::nullopt;
}

std::vector<std::string> known_spectrum_names() {
    std::vector<std::string> names;
    for (const NamedMetal& m : kMetals) {
        names.push_back(std::string("metal-") + m.name + "-eta");
        names.push_back(std::string("metal-") + m.name + "-k");
    }
    for (const NamedGlass& g : kGlasses) {
        names.emplace_back(g.name);
    }
    return names;
}

Rgb conductor_reflectance(const ComplexIor& ior) {
    return {normal_incidence(ior.eta.r, ior.k.r), normal_incidence(ior.eta.g, ior.k.g),
            normal_incidence(ior.eta.b, ior.k.b)};
}

Rgb blackbody_rgb(double kelvin) {
    // Planck's law up to a constant factor (the result is scaled to luminance 1 anyway).
    const auto planck = [kelvin](double lambda_nm) {
        const double c2 = 1.4387769e-2;  // h c / k_B, in m·K
        const double lambda = lambda_nm * 1e-9;
        return 1 / (std::pow(lambda_nm, 5) * std::expm1(c2 / (lambda * kelvin)));
    };
    double luminance = 0;
    const Rgb rgb = integrate_rgb(planck, &luminance);
    return luminance > 0 ? Rgb{rgb.r / luminance, rgb.g / luminance, rgb.b / luminance} : Rgb{0, 0, 0};
}

Rgb sampled_spectrum_rgb(const std::vector<double>& pairs, bool unit_luminance) {
    double luminance = 0, white_luminance = 0;
    const Rgb rgb = integrate_rgb([&](double lambda) { return interpolate(pairs, lambda); }, &luminance);
    // Divided channel by channel by the colour of the constant spectrum 1, so that a flat spectrum is
    // grey (equal-energy white is slightly pink in sRGB, whose white is D65).
    const Rgb white = integrate_rgb([](double) { return 1.0; }, &white_luminance);
    Rgb balanced{rgb.r / white.r, rgb.g / white.g, rgb.b / white.b};
    const double y = balanced.luminance();
    if (unit_luminance) {
        return y > 0 ? Rgb{balanced.r / y, balanced.g / y, balanced.b / y} : Rgb{0, 0, 0};
    }
    return {std::max(balanced.r, 0.0), std::max(balanced.g, 0.0), std::max(balanced.b, 0.0)};
}

Rgb sampled_spectrum_at_rgb_wavelengths(const std::vector<double>& pairs) {
    return {interpolate(pairs, kRgbWavelengths[0]), interpolate(pairs, kRgbWavelengths[1]),
            interpolate(pairs, kRgbWavelengths[2])};
}

}  // namespace glint::pbrt_spectra
