// Radiance read back from a rendered PFM against Lambert's law computed by hand:
// L = ρ/π · I cos θ / r² for a matte sphere lit by one point light (errata to paper eq. 14–15).
#include <gtest/gtest.h>

#include "glint/image/image_io.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

constexpr int kSize = 101;
constexpr double kFovDegrees = 20;
const Vec3 kEye{0, 0, 10};
const Vec3 kLight{3, 4, 5};
constexpr double kIntensity = 50;
constexpr double kAlbedo = 0.5;

// The analytic radiance seen through film point (fx, fy), without any of glint's code: the camera
// at kEye looks down −z, so the view plane is x right, y up, at distance d = (h/2)/tan(fov/2).
double analytic_radiance(double fx, double fy) {
    const double d = 0.5 * kSize / std::tan(kFovDegrees * kPi / 360);
    const Vec3 dir = normalize(Vec3{fx - 0.5 * kSize, 0.5 * kSize - fy, -d});
    // Unit sphere at the origin: |e + t d|² = 1.
    const double b = dot(kEye, dir);
    const double disc = b * b - (dot(kEye, kEye) - 1);
    if (disc < 0) {
        return 0;
    }
    const Vec3 p = kEye + (-b - std::sqrt(disc)) * dir;
    const Vec3 to_light = kLight - p;
    const double r2 = dot(to_light, to_light);
    const double cos_theta = std::max(0.0, dot(p, to_light) / std::sqrt(r2));
    return kAlbedo / kPi * kIntensity * cos_theta / r2;
}

// The mean of the analytic radiance over pixel (x, y), on a fine grid.
double analytic_pixel(int x, int y) {
    constexpr int kGrid = 32;
    double sum = 0;
    for (int i = 0; i < kGrid; ++i) {
        for (int j = 0; j < kGrid; ++j) {
            sum += analytic_radiance(x + (i + 0.5) / kGrid, y + (j + 0.5) / kGrid);
        }
    }
    return sum / (kGrid * kGrid);
}

TEST(Lambert, PfmPixelsMatchTheAnalyticRadianceOfASphereLitByAPointLight) {
    test::TempDir dir;
    const std::string size = std::to_string(kSize);
    const auto scene = dir.write("lambert.yaml", R"(
render: {width: )" + size + ", height: " + size + R"(, samples: 64, sampler: jittered}
camera: {eye: [0, 0, 10], look_at: [0, 0, 0], fov: 20}
materials: {grey: {type: matte, albedo: 0.5}}
objects: [{type: sphere, center: [0, 0, 0], radius: 1, material: grey}]
lights: [{type: point, position: [3, 4, 5], intensity: 50}]
)");
    const auto out = dir / "lambert.pfm";
    const auto r = test::run_glint("render '" + scene.string() + "' -o '" + out.string() + "' --quiet");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const Image image = read_pfm(out);
    ASSERT_EQ(image.width, kSize);
    // The centre, pixels lit at various angles, one near the terminator, and the background.
    const std::pair<int, int> pixels[] = {{50, 50}, {60, 40}, {45, 58}, {70, 35}, {32, 50}, {50, 68}, {5, 5}};
    for (const auto& [x, y] : pixels) {
        const double expected = analytic_pixel(x, y);
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(image.pixel(x, y)[c], expected, 2e-3 * expected + 1e-6) << "pixel " << x << "," << y;
        }
    }
    EXPECT_GT(analytic_pixel(60, 40), 0.05);  // the test pixels are really lit
}

TEST(Lambert, AmbientLightAddsAlbedoTimesRadiance) {
    const Scene scene = test::scene_from_text(R"(
render: {width: 9, height: 9, samples: 4}
camera: {eye: [0, 0, 10], look_at: [0, 0, 0], fov: 2}
objects: [{type: sphere, radius: 1, material: {type: matte, albedo: [0.2, 0.4, 0.6]}}]
lights: [{type: ambient, radiance: 0.5}]
)");
    const Film film = test::render_film(scene);
    const Rgb c = film.pixel(4, 4);
    EXPECT_DOUBLE_EQ(c.r, 0.1);
    EXPECT_DOUBLE_EQ(c.g, 0.2);
    EXPECT_DOUBLE_EQ(c.b, 0.3);
}

}  // namespace
}  // namespace glint
