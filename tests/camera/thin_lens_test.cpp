#include "glint/camera/thin_lens.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <span>
#include <vector>

#include "camera/camera_test_util.hpp"
#include "glint/core/cpu.hpp"
#include "glint/core/hash.hpp"
#include "glint/image/image_io.hpp"
#include "glint/params/diagnostics.hpp"

namespace glint {
namespace {

using test::at_depth;
using test::camera_scene;
using test::kObliqueEye;
using test::kObliqueForward;
using test::kObliqueView;

// A regular n × n grid of lens samples covering the unit square, edges included (the edges map to the
// rim of the lens).
std::vector<Point2> lens_grid(int n) {
    std::vector<Point2> points;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            points.push_back({i / (n - 1.0), j / (n - 1.0)});
        }
    }
    return points;
}

TEST(ThinLens, PointsOnTheFocusPlaneAreSharp) {
    // Every lens sample's ray for a film point passes through the point of the focus plane that the
    // pinhole ray of that film point hits.
    const Scene lens =
        camera_scene("{type: thin-lens, " + kObliqueView + ", lens_radius: 0.3, focus_distance: 4}");
    const Scene pinhole = camera_scene("{type: pinhole, " + kObliqueView + "}");
    const Vec3& eye = kObliqueEye;
    const Vec3& forward = kObliqueForward;
    for (const Point2 film : {Point2{100, 50}, Point2{3.5, 7.25}, Point2{180, 90}, Point2{150.5, 20}}) {
        const Vec3 focus_point = at_depth(pinhole.view.camera->generate_ray(film, {}), eye, forward, 4);
        double widest_origin = 0;
        for (const Point2 u : lens_grid(9)) {
            const Ray r = lens.view.camera->generate_ray(film, u);
            EXPECT_NEAR(length(r.direction), 1, 1e-12);
            // The ray starts on the lens: across the view direction, within the lens radius of the eye.
            EXPECT_NEAR(dot(r.origin - eye, forward), 0, 1e-12);
            EXPECT_LE(length(r.origin - eye), 0.3 + 1e-12);
            widest_origin = std::max(widest_origin, length(r.origin - eye));
            EXPECT_LT(length(at_depth(r, eye, forward, 4) - focus_point), 1e-12);
        }
        EXPECT_NEAR(widest_origin, 0.3, 1e-12);  // the lens's rim is used
    }
}

TEST(ThinLens, NearPlaneStartsRaysOnItAndKeepsTheFocus) {
    // With near 1.5 each ray starts on the plane across the view at depth 1.5 from the lens, on the
    // line of the near-0 ray from the same lens point, and still passes through the focus point.
    const std::string view = "type: thin-lens, " + kObliqueView + ", lens_radius: 0.3, focus_distance: 4";
    const Scene plain = camera_scene("{" + view + "}");
    const Scene clipped = camera_scene("{" + view + ", near: 1.5}");
    const Vec3& eye = kObliqueEye;
    const Vec3& forward = kObliqueForward;
    for (const Point2 film : {Point2{100, 50}, Point2{3.5, 7.25}, Point2{180, 90}}) {
        for (const Point2 u : lens_grid(5)) {
            const Ray from_lens = plain.view.camera->generate_ray(film, u);
            const Ray from_near = clipped.view.camera->generate_ray(film, u);
            EXPECT_NEAR(dot(from_near.origin - eye, forward), 1.5, 1e-12);
            EXPECT_LT(length(from_near.origin - at_depth(from_lens, eye, forward, 1.5)), 1e-12);
            EXPECT_LT(length(from_near.direction - from_lens.direction), 1e-15);
            EXPECT_LT(length(at_depth(from_near, eye, forward, 4) - at_depth(from_lens, eye, forward, 4)),
                      1e-12);
        }
    }
}

TEST(ThinLens, RaysTogetherAreOneByOnesRays) {
    // generate_rays makes four rays at a time in AVX2 lanes (where the CPU has them), the rest one by one:
    // each ray must be generate_ray's to the bit. Lens points: a grid with the edges, the centre (where
    // the concentric map divides 0 by 0), the diagonals |a| = |b| and the axes a = 0, b = 0 on it, and
    // random points; counts 0 to 13, so that every tail length follows the groups of four.
    if (!cpu_has_avx2_and_fma()) {
        GTEST_SKIP() << "no AVX2 and FMA on this CPU: generate_rays calls generate_ray, nothing to compare";
    }
    std::vector<Point2> lens = lens_grid(9);
    std::vector<Point2> film;
    for (std::uint32_t i = 0; i < 200; ++i) {
        const SampleKey key{21, i, 0, 0};
        lens.push_back({key.uniform(0), key.uniform(1)});
    }
    for (std::size_t i = 0; i < lens.size(); ++i) {
        film.push_back({200 * std::fmod(0.37 * static_cast<double>(i), 1.0),
                        100 * std::fmod(0.61 * static_cast<double>(i), 1.0)});
    }
    for (const std::string extra : {"", ", near: 1.5", ", near: 1.5, near_shape: sphere"}) {
        const Scene scene = camera_scene("{type: thin-lens, " + kObliqueView +
                                         ", lens_radius: 0.3, focus_distance: 4" + extra + "}");
        const Camera& camera = *scene.view.camera;
        for (std::size_t count = 0; count <= 13; ++count) {
            for (std::size_t first = 0; first + count <= lens.size(); first += 7) {
                std::vector<Ray> together(count);
                camera.generate_rays(std::span(film).subspan(first, count),
                                     std::span(lens).subspan(first, count), together);
                for (std::size_t i = 0; i < count; ++i) {
                    const Ray alone = camera.generate_ray(film[first + i], lens[first + i]);
                    ASSERT_EQ(std::memcmp(&together[i], &alone, sizeof(Ray)), 0)
                        << extra << ": sample " << first + i << " of a call of " << count;
                }
            }
        }
    }
}

TEST(ThinLens, FocusDistanceDefaultsToTheLookAtPoint) {
    const Scene scene =
        camera_scene("{type: thin-lens, eye: [0, 1, 6], look_at: [0.5, 0, -1], lens_radius: 0.5}");
    for (const Point2 u : lens_grid(5)) {
        const Ray r = scene.view.camera->generate_ray({100, 50}, u);  // the image centre
        EXPECT_LT(test::distance_to_line(r, {0.5, 0, -1}), 1e-12);
    }
}

TEST(ThinLens, BlursAPointIntoADiskOfTheCircleOfConfusionDiameter) {
    // Eye at the origin looking down −z, d = 100 pixels, lens radius r = 0.5, focus at z_f = 5.
    // A point Q at depth z is seen from lens point L by the film point whose ray goes L → Q; that ray
    // meets the focus plane at F = L + (Q − L)·z_f/z. Check the camera's ray through F's film point from L
    // does pass through Q, and that the F of all lens points spread over a disk of diameter
    // 2r·|z − z_f|/z on the focus plane (errata §4.1, object side).
    const double r = 0.5, z_f = 5, d = 100;
    const Scene scene = camera_scene(
        "{type: thin-lens, eye: [0, 0, 0], look_at: [0, 0, -1], view_distance: 100, "
        "lens_radius: 0.5, focus_distance: 5}");
    for (const double z : {2.0, 4.0, 8.0, 20.0}) {
        const Vec3 q{0.3, -0.2, -z};
        double widest = 0;
        std::vector<Vec3> focus_points;
        for (const Point2 u : lens_grid(17)) {
            const Ray through_centre = scene.view.camera->generate_ray({100, 50}, u);
            const Vec3 lens_point = through_centre.origin;
            const Vec3 f = lens_point + (q - lens_point) * (z_f / z);
            // The film point whose pinhole ray hits F: (w/2 + d·F.x/z_f, h/2 − d·F.y/z_f).
            const Point2 film{100 + d * f.x / z_f, 50 - d * f.y / z_f};
            const Ray ray = scene.view.camera->generate_ray(film, u);
            EXPECT_LT(length(ray.origin - lens_point), 1e-12);
            EXPECT_LT(test::distance_to_line(ray, q), 1e-9) << "z = " << z;
            for (const Vec3& other : focus_points) {
                widest = std::max(widest, length(other - f));
            }
            focus_points.push_back(f);
        }
        EXPECT_NEAR(widest, 2 * r * std::abs(z - z_f) / z, 1e-9) << "z = " << z;
    }
}

TEST(ThinLens, RaysOfOneFilmPointSpreadAwayFromTheFocusPlane) {
    // Measured straight from the camera's rays: the rays of one film point cross the plane at depth z in
    // a disk of diameter 2r·|z − z_f|/z_f (similar triangles about the focus point); seen from the lens
    // centre that disk is 2r·|z − z_f|/z wide on the focus plane, the circle of confusion above.
    const double r = 0.4, z_f = 6;
    const Scene scene = camera_scene(
        "{type: thin-lens, eye: [0, 0, 0], look_at: [0, 0, -6], fov: 60, "
        "lens_radius: 0.4}");
    for (const double z : {1.5, 3.0, 12.0, 30.0}) {
        std::vector<Vec3> crossings;
        double widest = 0;
        for (const Point2 u : lens_grid(17)) {
            const Vec3 p = at_depth(scene.view.camera->generate_ray({130.25, 20.5}, u), {}, {0, 0, -1}, z);
            for (const Vec3& other : crossings) {
                widest = std::max(widest, length(other - p));
            }
            crossings.push_back(p);
        }
        EXPECT_NEAR(widest, 2 * r * std::abs(z - z_f) / z_f, 1e-9) << "z = " << z;
        EXPECT_NEAR(widest * z_f / z, 2 * r * std::abs(z - z_f) / z, 1e-9);
    }
}

TEST(ThinLens, FStopAndFocalLengthGiveTheLensRadius) {
    // N = f/D: a 50 mm lens at f/2.8 has an aperture 17.86 mm across, radius f/(2N).
    EXPECT_DOUBLE_EQ(lens_radius_from_f_stop(0.05, 2.8), 0.05 / 5.6);
    const Scene scene = camera_scene(
        "{type: thin-lens, eye: [0, 0, 0], look_at: [0, 0, -3], f_stop: 2.8, "
        "focal_length: 0.05}");
    const auto* camera = dynamic_cast<const ThinLensCamera*>(scene.view.camera.get());
    ASSERT_NE(camera, nullptr);
    EXPECT_DOUBLE_EQ(camera->lens_radius(), 0.05 / 5.6);
    EXPECT_DOUBLE_EQ(camera->focus_distance(), 3);
    // The rim of the lens square lands on the aperture's edge.
    EXPECT_NEAR(length(scene.view.camera->generate_ray({100, 50}, {1, 0.5}).origin), 0.05 / 5.6, 1e-15);
}

TEST(ThinLens, ZeroLensRadiusIsThePinhole) {
    const std::string view = "eye: [1, 2, 3], look_at: [0, 0, 0], fov: 30";
    const Scene lens = camera_scene("{type: thin-lens, " + view + ", lens_radius: 0}");
    const Scene pinhole = camera_scene("{" + view + "}");
    for (const Point2 film : {Point2{0, 0}, Point2{77.7, 12.5}, Point2{199.9, 99.9}}) {
        const Ray a = lens.view.camera->generate_ray(film, {0.9, 0.1});
        const Ray b = pinhole.view.camera->generate_ray(film, {});
        EXPECT_EQ(a.origin, b.origin);
        EXPECT_LT(length(a.direction - b.direction), 1e-15);
    }
}

using test::camera_error;

TEST(ThinLens, RejectsMissingOrConflictingApertures) {
    EXPECT_NE(camera_error("{type: thin-lens}").find("needs an aperture"), std::string::npos);
    EXPECT_NE(camera_error("{type: thin-lens, lens_radius: 0.1, f_stop: 2}").find("not both"),
              std::string::npos);
    EXPECT_NE(camera_error("{type: thin-lens, f_stop: 2}").find("go together"), std::string::npos);
    EXPECT_NE(camera_error("{type: thin-lens, lens_radius: -1}").find("lens_radius"), std::string::npos);
    EXPECT_NE(camera_error("{type: thin-lens, f_stop: 2, focal_length: 6}").find("nearer than f"),
              std::string::npos);
    EXPECT_NE(camera_error("{type: thin-lens, lens_radius: 1, focus_distance: 0}").find("focus_distance"),
              std::string::npos);
}

// The second moment Σ I·|p − centroid|² / Σ I of an image's first channel, in pixels².
double second_moment(const Image& image) {
    double total = 0, cx = 0, cy = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const double v = image.pixel(x, y)[0];
            total += v;
            cx += v * (x + 0.5);
            cy += v * (y + 0.5);
        }
    }
    cx /= total;
    cy /= total;
    double moment = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            moment += image.pixel(x, y)[0] * (sqr(x + 0.5 - cx) + sqr(y + 0.5 - cy));
        }
    }
    return moment / total;
}

TEST(ThinLens, RenderedBlurOfASmallSphereHasTheCircleOfConfusionDiameter) {
    // A small uniformly bright sphere (matte under ambient light only, on black) at depth z = 10, the
    // lens focused at z_f = 5 with r = 1.5: its image is a uniform disk of diameter 2r·|z − z_f|/z = 1.5
    // on the focus plane, 30 pixels with d = 100 (one pixel is z_f/d = 0.05 there). Blurring convolves,
    // and second moments add under convolution: a uniform disk of radius b has second moment b²/2, so
    // b² = 2·(moment blurred − moment in focus), whatever the sphere's own small image and the pixels add.
    test::TempDir dir;
    const auto render = [&](const std::string& name, double lens_radius) {
        const auto scene = dir.write(name + ".yaml", R"(
render: {width: 64, height: 64, samples: 256, sampler: jittered}
camera: {type: thin-lens, eye: [0, 0, 0], look_at: [0, 0, -1], view_distance: 100, focus_distance: 5,
         lens_radius: )" + std::to_string(lens_radius) + R"(}
background: 0
materials: {white: {type: matte, albedo: 1}}
objects: [{type: sphere, center: [0, 0, -10], radius: 0.2, material: white}]
lights: [{type: ambient, radiance: 1}]
)");
        const auto out = dir / (name + ".pfm");
        const auto r = test::run_glint("render '" + scene.string() + "' -o '" + out.string() + "' --quiet");
        EXPECT_EQ(r.exit_code, 0) << r.output;
        return read_pfm(out);
    };
    const double sharp = second_moment(render("sharp", 0));
    const double blurred = second_moment(render("blurred", 1.5));
    const double diameter_pixels = 2 * std::sqrt(2 * (blurred - sharp));
    const double expected_pixels = (2 * 1.5 * std::abs(10.0 - 5.0) / 10.0) / (5.0 / 100.0);
    RecordProperty("measured_diameter_pixels", std::to_string(diameter_pixels));
    EXPECT_NEAR(diameter_pixels, expected_pixels, 0.05 * expected_pixels) << "sharp moment " << sharp;
}

TEST(ThinLens, RenderedHorizonEdgeBlursByTheLensDiameter) {
    // An edge: the horizon of an unlit floor 1000 units below the eye against a white sky. Its points lie
    // at infinity, where the circle of confusion 2r·|z − z_f|/z on the focus plane tends to the lens
    // diameter 2r: seen from lens point L the horizon shifts by L's offset, so the sharp edge is smeared
    // by the lens disk. With r = 0.15, z_f = 1 and d = 100 pixels (0.01 units a pixel on the focus
    // plane) that disk is 30 pixels across. Floor points within 30 pixels of the horizon are ≥ 3333 units
    // away, where the blur differs from 2r by < 0.03%.
    // The edge's profile across rows is the fraction of the disk beyond each row; its derivative (the
    // line spread) has variance b²/4 for a disk of radius b, and variances add under convolution, so
    // b² = 4·(variance blurred − variance in focus) whatever the pixels add.
    test::TempDir dir;
    const auto line_spread_variance = [&](const std::string& name, double lens_radius) {
        const auto scene = dir.write(name + ".yaml", R"(
render: {width: 48, height: 64, samples: 256, sampler: jittered}
camera: {type: thin-lens, eye: [0, 1000, 0], look_at: [0, 1000, -1], view_distance: 100, focus_distance: 1,
         lens_radius: )" + std::to_string(lens_radius) + R"(}
background: 1
materials: {grey: {type: matte, albedo: 0.5}}
objects: [{type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: grey}]
)");
        const auto out = dir / (name + ".pfm");
        const auto r = test::run_glint("render '" + scene.string() + "' -o '" + out.string() + "' --quiet");
        EXPECT_EQ(r.exit_code, 0) << r.output;
        const Image image = read_pfm(out);
        std::vector<double> profile(image.height, 0);  // the sky's share of each row
        for (int y = 0; y < image.height; ++y) {
            for (int x = 0; x < image.width; ++x) {
                profile[y] += image.pixel(x, y)[0] / image.width;
            }
        }
        EXPECT_NEAR(profile.front(), 1, 1e-6);  // the edge lies well inside the image
        EXPECT_NEAR(profile.back(), 0, 1e-6);
        double total = 0, mean = 0, second = 0;
        for (int y = 0; y + 1 < image.height; ++y) {
            const double spread = profile[y] - profile[y + 1];  // at the boundary y + 1 between the rows
            total += spread;
            mean += spread * (y + 1);
            second += spread * sqr(y + 1);
        }
        mean /= total;
        return second / total - mean * mean;
    };
    const double sharp = line_spread_variance("sharp", 0);
    const double blurred = line_spread_variance("blurred", 0.15);
    const double diameter_pixels = 2 * std::sqrt(4 * (blurred - sharp));
    RecordProperty("measured_edge_blur_pixels", std::to_string(diameter_pixels));
    EXPECT_NEAR(diameter_pixels, 30, 0.05 * 30) << "in-focus variance " << sharp;
}

}  // namespace
}  // namespace glint
