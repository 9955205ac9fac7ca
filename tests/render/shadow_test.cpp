// Hard shadows from shadow rays, and no shadow acne at any scene scale.
#include <gtest/gtest.h>

#include "test_util.hpp"

namespace glint {
namespace {

// A floor under a point light, seen at an angle, with the whole scene scaled by `s` (the intensity by
// s² so that radiance stays the same). Every pixel must show the unshadowed Lambert value computed by
// hand for its centre (within the variation across one pixel): a dark speck would be the floor
// shadowing itself.
void expect_no_acne(double s) {
    const auto num = [](double v) { return std::to_string(v); };
    constexpr int kWidth = 48, kHeight = 32;
    const Scene scene = test::scene_from_text(
        "render: {width: 48, height: 32, samples: 1, sampler: random}\n"
        "camera: {eye: [0, " +
        num(3 * s) + ", " + num(6 * s) +
        "], look_at: [0, 0, 0], fov: 30}\n"
        "objects: [{type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, albedo: 1}}]\n"
        "lights: [{type: point, position: [0, " +
        num(10 * s) + ", 0], intensity: " + num(100 * s * s) + "}]\n");
    const Film film = test::render_film(scene);
    // The pinhole camera by the errata's formulas, and L = 1/π · I cos θ / r² with cos θ = 10s / r.
    const Vec3 eye{0, 3 * s, 6 * s};
    const Vec3 w = normalize(eye), u = normalize(cross({0, 1, 0}, w)), v = cross(w, u);
    const double d = 0.5 * kHeight / std::tan(radians(15));
    const auto expected_at = [&](double fx, double fy) {
        const Vec3 dir = (fx - 0.5 * kWidth) * u + (0.5 * kHeight - fy) * v - d * w;
        const Vec3 p = eye + (-eye.y / dir.y) * dir;
        const double r = length(Vec3{0, 10 * s, 0} - p);
        return 100 * s * s * (10 * s / r) / (kPi * r * r);
    };
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            // The sample lies somewhere in the pixel: the value is between the extremes at its corners
            // (up to 0.1%, for the pixel that holds the peak under the light).
            const double corners[] = {expected_at(x, y), expected_at(x + 1, y), expected_at(x, y + 1),
                                      expected_at(x + 1, y + 1)};
            const double lo = *std::min_element(std::begin(corners), std::end(corners));
            const double hi = *std::max_element(std::begin(corners), std::end(corners));
            const double v_xy = film.pixel(x, y).r;
            EXPECT_GE(v_xy, lo * (1 - 1e-3)) << "pixel " << x << "," << y << " at scale " << s;
            EXPECT_LE(v_xy, hi * (1 + 1e-3)) << "pixel " << x << "," << y << " at scale " << s;
        }
    }
}

TEST(Shadows, NoAcneAtTinyUnitAndHugeScales) {
    expect_no_acne(1e-3);
    expect_no_acne(1.0);
    expect_no_acne(1e4);
}

TEST(Shadows, ABlockerCastsAnUmbraLitByTheAmbientTermOnly) {
    // A sphere of radius 0.5 two units under a point light: its shadow on the floor is a disk of radius
    // 4·tan(asin(0.5/2)) ≈ 1.03 around the origin, which the camera sees at the image centre.
    const Scene scene = test::scene_from_text(R"(
render: {width: 21, height: 21, samples: 4}
camera: {eye: [0, 3, 6], look_at: [0, 0, 0], fov: 30}
objects:
  - {type: plane, normal: [0, 1, 0], material: {type: matte, albedo: 0.5}}
  - {type: sphere, center: [0, 2, 0], radius: 0.5, material: {type: matte, albedo: 0.5}}
lights:
  - {type: point, position: [0, 4, 0], intensity: 10}
  - {type: ambient, radiance: 0.2}
)");
    const Film film = test::render_film(scene);
    // In the umbra only the ambient term remains: ρ · L_a = 0.5 · 0.2.
    EXPECT_DOUBLE_EQ(film.pixel(10, 10).r, 0.1);
    // The bottom row sees the floor near z = 2.6, outside the shadow: ambient + 0.5/π · 10 cos θ / r²
    // ≈ 0.1 + 0.058.
    EXPECT_NEAR(film.pixel(10, 20).r, 0.158, 0.01);
}

}  // namespace
}  // namespace glint
