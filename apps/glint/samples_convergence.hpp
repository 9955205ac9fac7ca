#pragma once

#include <cstdint>
#include <string>

namespace glint_cli {

// `glint samples --convergence`: RMSE against samples per pixel for every pattern, on an edge and a
// smooth integrand (glint/sampling/convergence.hpp), for counts 1, 4, 16, … up to max_count over
// `pixels` randomisations. Prints a markdown table with the fitted slopes; with a .png output, also
// draws the log–log plot there.
void run_convergence(std::uint32_t pixels, std::uint32_t max_count, std::uint64_t seed,
                     const std::string& png_output);

}  // namespace glint_cli
