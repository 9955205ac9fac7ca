// Progressive rendering: passes in order add up to exactly what render() produces.
#include "glint/render/progressive.hpp"
#include "glint/scene/scene_set.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <limits>
#include <string>
#include <vector>

#include "glint/bvh/wide_bvh.hpp"
#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

Scene small_default_scene(std::uint32_t spp) {
    RenderFlags o;
    o.width = 40;
    o.height = 23;  // not a multiple of the tile size
    o.samples_per_pixel = spp;
    return build_scene(default_scene(), o);
}

TEST(ProgressiveRender, AllPassesGiveTheBitsOfRender) {
    const Scene scene = small_default_scene(25);  // jittered: 25 = 5×5, passes 2+4+8+11
    // render() with no one watching its passes takes them 16 samples at a time (16 + 9): the same bits
    // as the growing passes below.
    Film expected(40, 23);
    const RenderStats stats = render(scene, expected);

    ProgressiveRender progressive(*scene.world, scene.view);
    EXPECT_EQ(progressive.target_samples(), 25u);
    std::vector<std::uint32_t> done_after_pass;
    while (!progressive.complete()) {
        ASSERT_TRUE(progressive.next_pass());
        done_after_pass.push_back(progressive.samples_done());
    }
    EXPECT_EQ(done_after_pass, (std::vector<std::uint32_t>{2, 6, 14, 25}));
    EXPECT_EQ(progressive.film().to_image().rgb, expected.to_image().rgb);
    EXPECT_EQ(progressive.stats().rays.total(), stats.rays.total());
    EXPECT_EQ(progressive.film().sample_count(39, 22), 25u);
}

// A render of `target` samples a pixel of a 3×2 image (one tile), in passes sized by `sizes`: the
// samples each pass took.
std::vector<std::uint32_t> pass_sizes(std::uint32_t target, PassSizes sizes) {
    // A pattern that takes any count as it is (jittered rounds it up to a square).
    const Scene scene = test::scene_from_text(
        "render: {width: 3, height: 2, sampler: random, samples: " + std::to_string(target) + "}\n");
    ProgressiveRender progressive(*scene.world, scene.view, sizes);
    EXPECT_EQ(progressive.target_samples(), target);
    std::vector<std::uint32_t> taken;
    while (!progressive.complete()) {
        taken.push_back(progressive.next_pass_samples());
        const std::uint32_t before = progressive.samples_done();
        EXPECT_TRUE(progressive.next_pass());
        EXPECT_EQ(progressive.samples_done() - before, taken.back());
    }
    return taken;
}

TEST(ProgressiveRender, PassesGrowAndLeaveNoSmallLastPass) {
    // Passes of 2, 4, 8, then 16 samples (the first of two: a pass of one draws its samples' points one
    // by one), and a remainder of at most half a pass taken with the last one when both fit in one pass:
    // 3 samples are one pass, and 16 are 2 + 4 + 10, not 2 + 4 + 8 + 2.
    const auto passes = [](std::uint32_t target) { return pass_sizes(target, PassSizes::kGrowing); };
    using Passes = std::vector<std::uint32_t>;
    EXPECT_EQ(passes(1), (Passes{1}));
    EXPECT_EQ(passes(2), (Passes{2}));
    EXPECT_EQ(passes(3), (Passes{3}));
    EXPECT_EQ(passes(4), (Passes{2, 2}));
    EXPECT_EQ(passes(8), (Passes{2, 6}));
    EXPECT_EQ(passes(16), (Passes{2, 4, 10}));
    EXPECT_EQ(passes(25), (Passes{2, 4, 8, 11}));
    EXPECT_EQ(passes(32), (Passes{2, 4, 8, 16, 2}));
    EXPECT_EQ(passes(40), (Passes{2, 4, 8, 16, 10}));
    EXPECT_EQ(passes(64), (Passes{2, 4, 8, 16, 16, 16, 2}));
    for (std::uint32_t target = 1; target <= 100; ++target) {
        const Passes sizes = passes(target);
        std::uint32_t done = 0;
        for (std::size_t i = 0; i < sizes.size(); ++i) {
            EXPECT_GE(sizes[i], 1u) << target;
            EXPECT_LE(sizes[i], 16u) << target;  // kMaxPassSamples: a batch's buffers
            // The first picture comes soon: a first pass of at most 3 samples (2, or all of a target of 3),
            // and no later pass more than twice the samples before it and two (a remainder merged).
            EXPECT_LE(sizes[i], i == 0 ? 3u : 2 * done + 2) << target;
            if (i > 0 && i + 1 == sizes.size() && sizes[i - 1] + sizes[i] <= 16) {
                // No last pass below half the one before, when the two fit in one.
                EXPECT_GE(2 * sizes[i], sizes[i - 1]) << target;
            }
            done += sizes[i];
        }
        EXPECT_EQ(done, target);
    }
}

TEST(ProgressiveRender, FullPassesTakeSixteenSamplesFromTheFirst) {
    using Passes = std::vector<std::uint32_t>;
    EXPECT_EQ(pass_sizes(1, PassSizes::kFull), (Passes{1}));
    EXPECT_EQ(pass_sizes(3, PassSizes::kFull), (Passes{3}));
    EXPECT_EQ(pass_sizes(16, PassSizes::kFull), (Passes{16}));
    EXPECT_EQ(pass_sizes(17, PassSizes::kFull), (Passes{16, 1}));
    EXPECT_EQ(pass_sizes(32, PassSizes::kFull), (Passes{16, 16}));
    EXPECT_EQ(pass_sizes(40, PassSizes::kFull), (Passes{16, 16, 8}));
}

// render() grows its passes only for a caller that sees or stops at their ends (a time limit, or
// pass_done, which writes checkpoints), and takes 16 samples at a time otherwise, Ctrl-C's
// stop_after_pass included. Seen through the progress of a one-tile image, reported once a pass (and
// once more at the end), as a fraction of the samples.
TEST(ProgressiveRender, RenderGrowsItsPassesOnlyWhenTheirEndsAreWatched) {
    const Scene scene =
        test::scene_from_text("render: {width: 3, height: 2, sampler: random, samples: 32}\n");
    const auto progress = [&](RenderCallbacks callbacks) {
        std::vector<double> fractions;
        callbacks.progress = [&](double fraction) { fractions.push_back(fraction); };
        Film film(3, 2);
        render(scene, film, callbacks);
        return fractions;
    };
    using Fractions = std::vector<double>;
    const Fractions full{16.0 / 32, 1, 1};
    const Fractions growing{2.0 / 32, 6.0 / 32, 14.0 / 32, 30.0 / 32, 1, 1};  // 2 + 4 + 8 + 16 + 2
    EXPECT_EQ(progress({}), full);
    const std::atomic<bool> never{false};
    RenderCallbacks stoppable;
    stoppable.stop_after_pass = &never;
    EXPECT_EQ(progress(stoppable), full);
    RenderCallbacks limited;
    limited.time_limit_seconds = 1e9;
    EXPECT_EQ(progress(limited), growing);
    RenderCallbacks watched;
    watched.pass_done = [](const Film&, std::uint32_t) {};
    EXPECT_EQ(progress(watched), growing);
}

// Renders `jobs` at once with render_batch and checks that each sample gets, to the bit, what
// render_sample gives it alone, and that the same rays are counted. `alone` receives render_sample's
// radiances, for the caller's own counts; `what` names the case in failures. (Fatal failures return from
// here: callers wrap the call in ASSERT_NO_FATAL_FAILURE.)
void check_batch_gives_render_sample_bits(const Scene& scene, const Integrator& traced,
                                          const std::vector<SampleJob>& jobs, const std::string& what,
                                          std::vector<Rgb>& alone) {
    // NaN, so that a sample render_batch leaves unwritten fails.
    std::vector<Rgb> together(jobs.size(), Rgb(std::numeric_limits<double>::quiet_NaN()));
    RayCounters rays_together;
    render_batch(*scene.world, scene.view, traced, jobs, rays_together, together);
    RayCounters rays_alone;
    alone.clear();
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        const SampleJob& job = jobs[i];
        alone.push_back(
            render_sample(*scene.world, scene.view, traced, job.x, job.y, job.key.sample(), rays_alone));
        ASSERT_EQ(together[i].r, alone[i].r) << what << ", sample " << i;
        ASSERT_EQ(together[i].g, alone[i].g) << what << ", sample " << i;
        ASSERT_EQ(together[i].b, alone[i].b) << what << ", sample " << i;
    }
    ASSERT_EQ(rays_together.camera, rays_alone.camera) << what;
    ASSERT_EQ(rays_together.shadow, rays_alone.shadow) << what;
    ASSERT_EQ(rays_together.secondary, rays_alone.secondary) << what;
}

TEST(ProgressiveRender, APassOfSeveralSamplesGivesEachTheBitsOfRenderSample) {
    // A pass of two or more samples hashes each pixel's dimensions once (PixelHashes) and hands the
    // samples keys that read them; a one-sample pass and render_sample hash as they go. The passes go to
    // the camera and the integrator in batches of whole pixels (16 pixels' samples in a pass of one, 8 in
    // a pass of two, 5 in a pass of three, 2 in a pass of seven or eight, a pixel's alone in a pass of
    // sixteen), which end where the tile ends. With sobol and a lens (film and lens read the cached
    // dimensions) and a path of bounces (later ones too), the film must hold, to the bit, the sum of
    // render_sample's radiances in sample order: for 1 sample (one pass of one), 3 (one pass), 13 (2, 4,
    // 7) and 31 (2, 4, 8, 16 and a last pass of one), on an image of 7 × 5 pixels in one tile (35
    // pixels: no pass fills its last batch) and on one of 21 × 19 in several tiles of 16 × 16 (batches
    // cross rows; the 5 × 3 corner tile ends in a partial batch).
    for (const std::uint32_t samples : {1u, 3u, 13u, 31u}) {
        for (const auto& [width, height] : {std::pair{7, 5}, std::pair{21, 19}}) {
            const Scene scene = test::scene_from_text(
                "render: {width: " + std::to_string(width) + ", height: " + std::to_string(height) +
                ", samples: " + std::to_string(samples) +
                ", sampler: sobol, integrator: path}\n"
                "camera: {type: thin-lens, eye: [0, 1, 5], look_at: [0, 0.5, 0], fov: 40, lens_radius: 0.2}\n"
                "objects:\n"
                "  - {type: sphere, center: [0, 0.5, 0], radius: 0.5, material: {type: matte, albedo: [0.7, "
                "0.5, 0.3]}}\n"
                "  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, albedo: "
                "[0.5, 0.5, 0.5]}}\n"
                "lights:\n  - {type: point, position: [1, 3, 2], intensity: 20}\n"
                "background: [0.2, 0.3, 0.4]\n");
            ProgressiveRender progressive(*scene.world, scene.view);
            while (!progressive.complete()) {
                ASSERT_TRUE(progressive.next_pass());
            }
            ASSERT_EQ(progressive.samples_done(), samples);
            RayCounters rays;
            for (int y = 0; y < height; ++y) {
                for (int x = 0; x < width; ++x) {
                    Rgb sum;
                    for (std::uint32_t s = 0; s < samples; ++s) {
                        sum +=
                            render_sample(*scene.world, scene.view, progressive.integrator(), x, y, s, rays);
                    }
                    const Film::Pixel& film = progressive.film().raw_pixel(x, y);
                    ASSERT_EQ(film.count, samples) << x << ", " << y;
                    ASSERT_EQ(film.sum.r, sum.r) << samples << ": " << x << ", " << y;
                    ASSERT_EQ(film.sum.g, sum.g) << samples << ": " << x << ", " << y;
                    ASSERT_EQ(film.sum.b, sum.b) << samples << ": " << x << ", " << y;
                }
            }
            EXPECT_GT(rays.secondary, 0u);  // the paths bounced
        }
    }
}

TEST(ProgressiveRender, ABatchOfSeveralPixelsGivesEachSampleTheBitsOfRenderSample) {
    // render_batch takes samples of several pixels at once, as a pass of one or a few samples a pixel
    // hands them: each must get render_sample's bits and rays, through a fisheye whose corners see
    // nothing (black, left out of the call) and through a thin lens (rays made four at a time), for
    // batches of 1 to 20 samples (beyond 16 the samples go in two calls).
    const std::string fisheye = "{type: fisheye, eye: [0, 1, 5], look_at: [0, 0.5, 0], fov: 200}";
    const std::string thin_lens =
        "{type: thin-lens, eye: [0, 1, 5], look_at: [0, 0.5, 0], fov: 60, lens_radius: 0.2}";
    for (const std::string& camera : {fisheye, thin_lens}) {
        const Scene scene = test::scene_from_text(
            "render: {width: 7, height: 5, samples: 4, sampler: sobol, integrator: path}\n"
            "camera: " +
            camera +
            "\n"
            "objects:\n"
            "  - {type: sphere, center: [0, 0.5, 0], radius: 0.5, material: {type: dielectric, ior: 1.5}}\n"
            "  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, albedo: 0.5}}\n"
            "lights:\n  - {type: point, position: [1, 3, 2], intensity: 40}\n"
            "background: [0.2, 0.3, 0.4]\n");
        ProgressiveRender progressive(*scene.world, scene.view);
        const Integrator& traced = progressive.integrator();
        int unseen = 0;
        for (std::size_t count = 1; count <= 20; ++count) {
            // Pixels in row order from pixel number `count` (x = n mod 7, y = n / 7), the i-th with sample
            // i mod 3.
            std::vector<SampleJob> jobs;
            for (std::size_t i = 0; i < count; ++i) {
                const int pixel = static_cast<int>((count + i) % 35);
                const int x = pixel % 7, y = pixel / 7;
                const SampleHashes key(
                    SampleHashes::pixel_hash(scene.view.settings.seed, static_cast<std::uint32_t>(x),
                                             static_cast<std::uint32_t>(y)),
                    static_cast<std::uint32_t>(i % 3));
                jobs.push_back(SampleJob{x, y, key, camera_points(scene.view, key)});
            }
            std::vector<Rgb> alone;
            ASSERT_NO_FATAL_FAILURE(check_batch_gives_render_sample_bits(
                scene, traced, jobs, "a batch of " + std::to_string(count), alone));
            for (const SampleJob& job : jobs) {
                unseen += camera_ray(scene.view, job.points, job.x, job.y) ? 0 : 1;
            }
        }
        if (camera == fisheye) {
            EXPECT_GT(unseen, 0);  // the batches held samples the camera does not see
        }
    }
}

TEST(ProgressiveRender, SamplesTakenTogetherAreEachRenderSamplesBits) {
    // render_batch hands a pass's camera rays to the integrator together: the path tracer traces all
    // their first rays before any path goes on, the others one sample after the other. Each sample must
    // get, to the bit, what render_sample gives it alone, with the same rays counted: through a
    // fisheye whose corners see nothing (those samples are black and left out of the call), with the
    // firefly clamp, for 1 to 20 samples (beyond 16 the samples go in two calls) and from any first
    // sample. And through a thin lens, whose rays the camera makes four at a time.
    const std::string fisheye = "{type: fisheye, eye: [0, 1, 5], look_at: [0, 0.5, 0], fov: 200}";
    const std::string thin_lens =
        "{type: thin-lens, eye: [0, 1, 5], look_at: [0, 0.5, 0], fov: 60, lens_radius: 0.2, near: 0.5}";
    for (const std::string& camera : {fisheye, thin_lens}) {
        for (const char* integrator : {"path", "whitted", "raycast"}) {
            const Scene scene = test::scene_from_text(
                std::string(
                    "render: {width: 6, height: 6, samples: 4, sampler: sobol, clamp: 0.5, integrator: ") +
                integrator +
                "}\n"
                "camera: " +
                camera +
                "\n"
                "objects:\n"
                "  - {type: sphere, center: [0, 0.5, 0], radius: 0.5, material: {type: dielectric, ior: "
                "1.5}}\n"
                "  - {type: sphere, center: [1, 0.3, 0.5], radius: 0.3, material: {type: matte, albedo: "
                "[0.7, "
                "0.5, 0.3]}}\n"
                "  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, albedo: "
                "[0.5, "
                "0.5, 0.5]}}\n"
                "lights:\n  - {type: point, position: [1, 3, 2], intensity: 40}\n"
                "  - {type: area, radiance: 5, shape: {type: sphere, center: [-1, 2, 1], radius: 0.3}}\n"
                "background: [0.2, 0.3, 0.4]\n");
            ProgressiveRender progressive(*scene.world, scene.view);
            const Integrator& traced = progressive.integrator();
            int mixed_pixels = 0;  // pixels with samples both traced and left black (no camera ray)
            int clamped = 0;       // samples scaled down to the clamp
            for (const std::uint32_t count : {1u, 2u, 7u, 16u, 20u}) {
                for (const std::uint32_t first : {0u, 3u}) {
                    for (int y = 0; y < 6; ++y) {
                        for (int x = 0; x < 6; ++x) {
                            const std::uint64_t hash = SampleHashes::pixel_hash(
                                scene.view.settings.seed, static_cast<std::uint32_t>(x),
                                static_cast<std::uint32_t>(y));
                            const PixelHashes pixel(hash);
                            std::vector<FilmAndLens> points(count);
                            scene.view.sampler->camera_points(pixel, first, scene.view.camera->uses_lens(),
                                                              points);
                            std::vector<SampleJob> jobs;
                            for (std::uint32_t i = 0; i < count; ++i) {
                                jobs.push_back(SampleJob{x, y, SampleHashes(pixel, first + i), points[i]});
                            }
                            std::vector<Rgb> alone;
                            ASSERT_NO_FATAL_FAILURE(check_batch_gives_render_sample_bits(
                                scene, traced, jobs,
                                std::string(integrator) + " " + std::to_string(x) + ", " + std::to_string(y),
                                alone));
                            int unseen = 0;
                            for (std::uint32_t i = 0; i < count; ++i) {
                                unseen += camera_ray(scene.view, points[i], x, y) ? 0 : 1;
                                clamped += alone[i].max_component() == 0.5 ? 1 : 0;
                            }
                            mixed_pixels += unseen > 0 && unseen < static_cast<int>(count) ? 1 : 0;
                        }
                    }
                }
            }
            if (camera == fisheye) {
                EXPECT_GT(mixed_pixels, 0) << integrator;  // at the fisheye's edge
            }
            EXPECT_GT(clamped, 0) << integrator;
        }
    }
    // More camera rays than the path tracer takes together (16): each still gets radiance()'s bits.
    const Scene scene = test::scene_from_text(
        "render: {width: 4, height: 4, samples: 4, integrator: path}\n"
        "camera: {type: pinhole, eye: [0, 1, 5], look_at: [0, 0.5, 0], fov: 40}\n"
        "objects:\n"
        "  - {type: sphere, center: [0, 0.5, 0], radius: 0.5, material: {type: matte, albedo: 0.6}}\n"
        "  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: {type: matte, albedo: 0.5}}\n"
        "lights:\n  - {type: point, position: [1, 3, 2], intensity: 20}\n"
        "background: [0.2, 0.3, 0.4]\n");
    std::vector<Ray> camera_rays;
    std::vector<SampleStream> streams;
    for (std::uint32_t i = 0; i < 20; ++i) {
        const SampleHashes key(SampleHashes::pixel_hash(1, 2, 1), i);
        camera_rays.push_back(*camera_ray(scene.view, key, 2, 1));
        streams.emplace_back(*scene.view.sampler, key, kFirstIntegratorDimension);
    }
    std::vector<Rgb> together(20);
    RayCounters rays;
    scene.view.integrator->radiances(*scene.world, camera_rays, streams, rays, together);
    for (std::uint32_t i = 0; i < 20; ++i) {
        SampleStream stream(*scene.view.sampler, SampleHashes(SampleHashes::pixel_hash(1, 2, 1), i),
                            kFirstIntegratorDimension);
        const Rgb alone = scene.view.integrator->radiance(*scene.world, camera_rays[i], stream, rays);
        EXPECT_EQ(together[i].r, alone.r) << i;
        EXPECT_EQ(together[i].g, alone.g) << i;
        EXPECT_EQ(together[i].b, alone.b) << i;
    }
}

// A tree of spheres through a thin lens, where BvhAccelerator traces the camera rays of radiances as
// one packet, and then their first bounces as another: each path still gets radiance()'s bits, twin
// spheres (ties) included.
TEST(ProgressiveRender, APacketOfCameraRaysGivesEachPathItsOwnBits) {
    std::string text =
        "render: {width: 4, height: 4, samples: 16, integrator: path, max_depth: 6}\n"
        "camera: {type: thin-lens, eye: [0, 1, 6], look_at: [0, 0.5, 0], fov: 40, lens_radius: 0.1,"
        " focus_distance: 6}\n"
        "objects:\n";
    for (int i = 0; i < 40; ++i) {
        const double x = -2 + 0.1 * i;
        const double z = -1 + 0.05 * (i % 7);
        const std::string sphere = "  - {type: sphere, center: [" + std::to_string(x) + ", 0.3, " +
                                   std::to_string(z) +
                                   "], radius: 0.3, material: {type: matte, albedo: 0.7}}\n";
        text += sphere;
        if (i % 3 == 0) {
            text += sphere;  // a twin: rays that hit one meet the other at the same t
        }
    }
    text +=
        "  - {type: sphere, center: [0, -1000, 0], radius: 1000, material: {type: matte, albedo: 0.5}}\n"
        "background: [0.6, 0.7, 0.9]\n";
    const Scene scene = test::scene_from_text(text);
    EXPECT_EQ(scene.world->traces_packets(), WideBvh::uses_avx2());  // packets wherever the CPU has AVX2
    for (const auto& [x, y] : {std::pair{1u, 2u}, std::pair{2u, 1u}, std::pair{3u, 3u}}) {
        std::vector<Ray> camera_rays;
        std::vector<SampleStream> streams;
        for (std::uint32_t i = 0; i < 16; ++i) {
            const SampleHashes key(SampleHashes::pixel_hash(1, x, y), i);
            camera_rays.push_back(*camera_ray(scene.view, key, x, y));
            streams.emplace_back(*scene.view.sampler, key, kFirstIntegratorDimension);
        }
        std::vector<Rgb> together(16);
        RayCounters rays;
        scene.view.integrator->radiances(*scene.world, camera_rays, streams, rays, together);
        for (std::uint32_t i = 0; i < 16; ++i) {
            SampleStream stream(*scene.view.sampler, SampleHashes(SampleHashes::pixel_hash(1, x, y), i),
                                kFirstIntegratorDimension);
            const Rgb alone = scene.view.integrator->radiance(*scene.world, camera_rays[i], stream, rays);
            EXPECT_EQ(together[i].r, alone.r) << x << ' ' << y << ' ' << i;
            EXPECT_EQ(together[i].g, alone.g) << x << ' ' << y << ' ' << i;
            EXPECT_EQ(together[i].b, alone.b) << x << ' ' << y << ' ' << i;
        }
    }
}

TEST(ProgressiveRender, CancelledPassIsNotCounted) {
    const Scene scene = small_default_scene(4);
    ProgressiveRender progressive(*scene.world, scene.view);
    EXPECT_FALSE(progressive.next_pass([] { return true; }));
    EXPECT_EQ(progressive.samples_done(), 0u);
    EXPECT_FALSE(progressive.complete());
}

TEST(ProgressiveRender, CoarsePreviewRepeatsOneSamplePerBlock) {
    const Scene scene = small_default_scene(1);
    ProgressiveRender progressive(*scene.world, scene.view);
    Image preview;
    ASSERT_TRUE(progressive.coarse_preview(8, preview));
    ASSERT_EQ(preview.width, 40);
    ASSERT_EQ(preview.height, 23);
    // The block's value is the radiance of sample 0 at the block's centre pixel.
    RayCounters rays;
    const Rgb centre =
        render_sample(*scene.world, scene.view, progressive.integrator(), 12, 12, 0, rays);  // block (8..16)²
    for (int y = 8; y < 16; ++y) {
        for (int x = 8; x < 16; ++x) {
            EXPECT_EQ(preview.pixel(x, y)[0], static_cast<float>(centre.r));
            EXPECT_EQ(preview.pixel(x, y)[2], static_cast<float>(centre.b));
        }
    }
    // The last, partial block row (y 16..22) takes its own centre.
    const Rgb corner = render_sample(*scene.world, scene.view, progressive.integrator(), 36, 19, 0, rays);
    EXPECT_EQ(preview.pixel(39, 22)[1], static_cast<float>(corner.g));
    EXPECT_EQ(progressive.samples_done(), 0u);  // the film is untouched
    EXPECT_EQ(progressive.film().sample_count(0, 0), 0u);
}

// An integrator that returns NaN for one pixel and ∞ for another, 1 elsewhere.
class PoisonedIntegrator final : public Integrator {
  public:
    Rgb radiance(const World&, const Ray& ray, SampleStream&, RayCounters&) const override {
        if (ray.direction.x < -0.3 && ray.direction.y > 0.1) {
            return Rgb(std::numeric_limits<double>::quiet_NaN());
        }
        if (ray.direction.x > 0.3 && ray.direction.y < -0.1) {
            return Rgb(std::numeric_limits<double>::infinity());
        }
        return Rgb(1.0);
    }
};

// render() and the preview run the same loop: non-finite samples are left out of the film, counted, and
// the first named by pixel and sample, the same in both.
TEST(ProgressiveRender, NonFiniteSamplesAreCountedAndNamedNotZeroed) {
    Scene scene = small_default_scene(4);
    scene.view.integrator = std::make_unique<PoisonedIntegrator>();
    Film film(40, 23);
    const RenderStats stats = render(scene, film);
    ASSERT_GT(stats.nonfinite_samples, 0u);
    ASSERT_GE(stats.first_nonfinite_x, 0);
    // The named pixel lost samples, and its value is the mean of the finite ones, not darkened by zeros.
    const int x = stats.first_nonfinite_x, y = stats.first_nonfinite_y;
    EXPECT_LT(film.sample_count(x, y), 4u);
    if (film.sample_count(x, y) > 0) {
        EXPECT_EQ(film.pixel(x, y).r, 1.0);
    }
    std::uint64_t missing = 0;
    for (int j = 0; j < 23; ++j) {
        for (int i = 0; i < 40; ++i) {
            missing += 4 - film.sample_count(i, j);
        }
    }
    EXPECT_EQ(missing, stats.nonfinite_samples);
    // The sample named is one that render_sample finds non-finite (the loop's batches name the pixel
    // and sample of each result, not of another in the same batch).
    {
        ProgressiveRender alone(*scene.world, scene.view);
        RayCounters rays;
        EXPECT_FALSE(render_sample(*scene.world, scene.view, alone.integrator(), x, y,
                                   stats.first_nonfinite_sample, rays)
                         .is_finite());
    }

    ProgressiveRender progressive(*scene.world, scene.view);
    while (!progressive.complete()) {
        ASSERT_TRUE(progressive.next_pass());
    }
    const RenderStats preview = progressive.stats();
    EXPECT_EQ(preview.nonfinite_samples, stats.nonfinite_samples);
    EXPECT_EQ(preview.first_nonfinite_x, stats.first_nonfinite_x);
    EXPECT_EQ(preview.first_nonfinite_y, stats.first_nonfinite_y);
    EXPECT_EQ(preview.first_nonfinite_sample, stats.first_nonfinite_sample);
}

}  // namespace
}  // namespace glint

namespace glint {
namespace {

// The preview's continuous refinement: a finished render of 8 samples taken on to 24 is, bit for bit,
// a render of 24 (Sobol's points do not depend on the count); a pattern whose points do refuses.
TEST(ProgressiveRender, ExtendingAnExtendableTargetGivesTheBitsOfTheLargerRender) {
    const char* scene_text =
        "render: {width: 12, height: 8, samples: 8, integrator: path}\n"
        "objects:\n  - {type: sphere, radius: 1}\nlights:\n  - {type: environment, radiance: [0.5, 0.7, "
        "1]}\n";
    const Scene scene = test::scene_from_text(scene_text);
    ProgressiveRender progressive(*scene.world, scene.view);
    while (!progressive.complete()) {
        progressive.next_pass();
    }
    ASSERT_TRUE(progressive.extendable());
    EXPECT_FALSE(progressive.extend_target(8));  // not above the target
    ASSERT_TRUE(progressive.extend_target(24));
    EXPECT_FALSE(progressive.complete());
    while (!progressive.complete()) {
        progressive.next_pass();
    }
    EXPECT_EQ(progressive.samples_done(), 24u);
    RenderFlags more;
    more.samples_per_pixel = 24;
    const Film reference = test::render_film(test::scene_from_text(scene_text, more));
    EXPECT_EQ(progressive.film().to_image().rgb, reference.to_image().rgb);

    RenderFlags jittered;
    jittered.sampler = "jittered";
    const Scene other = test::scene_from_text(scene_text, jittered);
    ProgressiveRender fixed(*other.world, other.view);
    EXPECT_FALSE(fixed.extendable());
    EXPECT_FALSE(fixed.extend_target(64));
}

}  // namespace
}  // namespace glint
