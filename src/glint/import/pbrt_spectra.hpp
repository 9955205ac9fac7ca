// pbrt-v4 describes colours as spectra; glint renders linear sRGB. The reductions here turn the spectra
// a pbrt scene names or lists into RGB triples (docs/import-pbrt.md says how each is approximated).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "glint/core/color.hpp"

namespace glint::pbrt_spectra {

// The wavelengths (nm) at which glint samples a spectrum that has no RGB meaning of its own (indices
// of refraction, absorption): one for each of red, green and blue.
inline constexpr double kRgbWavelengths[3] = {630, 532, 465};

// A complex index of refraction η + iκ at kRgbWavelengths.
struct ComplexIor {
    Rgb eta, k;
};

// pbrt-v4's named metal spectra, by the metal's name in "metal-Au-eta": Ag, Al, Au, Cu, CuZn, MgO, TiO2.
std::optional<ComplexIor> named_metal(const std::string& metal);
// pbrt-v4's named glasses ("glass-BK7", …): the index at 550 nm.
std::optional<double> named_glass_ior(const std::string& name);
// Every name named_metal and named_glass_ior know, for messages.
std::vector<std::string> known_spectrum_names();

// The reflectance of a conductor at normal incidence, per channel: ((η−1)² + κ²) / ((η+1)² + κ²).
Rgb conductor_reflectance(const ComplexIor& ior);

// The linear sRGB colour of a blackbody at `kelvin`, scaled to luminance 1 (pbrt-v4 scales a light's
// spectrum to 1 nit before its `scale`).
Rgb blackbody_rgb(double kelvin);

// A piecewise-linear spectrum given as (wavelength, value) pairs, as linear sRGB under an equal-energy
// white; `unit_luminance` scales it to luminance 1 (for lights, as pbrt-v4 does).
Rgb sampled_spectrum_rgb(const std::vector<double>& pairs, bool unit_luminance);
// The same spectrum's values at kRgbWavelengths (for η and κ, which are not colours).
Rgb sampled_spectrum_at_rgb_wavelengths(const std::vector<double>& pairs);

}  // namespace glint::pbrt_spectra
