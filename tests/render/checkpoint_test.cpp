// Checkpoints (render/checkpoint.hpp): a render stopped after some passes, written to bytes, read back
// and resumed gives exactly the film of a render that never stopped — sums and counts, bit for bit, with
// another thread count for each part; a damaged or foreign checkpoint is refused with a message.
#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <limits>

#include "glint/render/checkpoint.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

// A path-traced scene with glass, so that paths differ in length and the sums in many bits; 40 samples
// take the passes 2, 4, 8, 16 and then 10 (after 2, 6, 14 and 30 samples a render can stop).
const char* kScene =
    "render: {width: 20, height: 14, samples: 40, integrator: path}\n"
    "camera: {eye: [0, 1, 5], look_at: [0, 0, 0], fov: 40}\n"
    "objects:\n"
    "  - {type: sphere, center: [-0.6, 0, 0], radius: 0.6, material: {type: dielectric, ior: 1.5}}\n"
    "  - {type: sphere, center: [0.7, 0, 0], radius: 0.5}\n"
    "  - {type: plane, point: [0, -0.6, 0], normal: [0, 1, 0]}\n"
    "lights:\n  - {type: environment, radiance: [0.5, 0.7, 1.0]}\n"
    "  - {type: point, position: [2, 3, 2], intensity: 20}\n";

void expect_same_film(const Film& a, const Film& b) {
    ASSERT_EQ(a.width(), b.width());
    ASSERT_EQ(a.height(), b.height());
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            const Film::Pixel& p = a.raw_pixel(x, y);
            const Film::Pixel& q = b.raw_pixel(x, y);
            ASSERT_EQ(std::memcmp(&p.sum, &q.sum, sizeof(p.sum)), 0) << x << ", " << y;
            ASSERT_EQ(std::memcmp(&p.luminance_squares, &q.luminance_squares, sizeof(double)), 0)
                << x << ", " << y;
            ASSERT_EQ(p.count, q.count) << x << ", " << y;
        }
    }
}

// Renders kScene with `threads`, stopping after the pass that reaches `stop_at` samples (0: never).
Checkpoint render_until(Scene& scene, int threads, std::uint32_t stop_at) {
    scene.view.settings.threads = threads;
    Checkpoint checkpoint;
    checkpoint.film = Film(scene.view.settings.width, scene.view.settings.height);
    std::atomic<bool> stop{false};
    RenderCallbacks callbacks;
    callbacks.stop_after_pass = &stop;
    callbacks.pass_done = [&](const Film&, std::uint32_t samples) {
        if (stop_at > 0 && samples >= stop_at) {
            stop = true;
        }
    };
    const RenderStats stats = render(*scene.world, scene.view, checkpoint.film, callbacks);
    checkpoint.samples_done = stats.samples_per_pixel;
    checkpoint.samples_asked = scene.view.settings.samples_per_pixel;
    checkpoint.scene_fingerprint = 42;
    return checkpoint;
}

TEST(Checkpoint, AResumedRenderHasTheBitsOfOneThatNeverStopped) {
    Scene scene = test::scene_from_text(kScene);
    const Checkpoint whole = render_until(scene, 2, 0);
    ASSERT_EQ(whole.samples_done, 40u);

    for (const std::uint32_t stop_at : {2u, 6u, 14u, 30u}) {
        const Checkpoint stopped = render_until(scene, 1, stop_at);
        ASSERT_EQ(stopped.samples_done, stop_at);
        const std::vector<unsigned char> bytes = encode_checkpoint(stopped);
        Checkpoint read = decode_checkpoint(bytes, "c.ckpt");
        EXPECT_EQ(read.samples_done, stop_at);
        EXPECT_EQ(read.samples_asked, 40u);
        EXPECT_EQ(read.scene_fingerprint, 42u);
        expect_same_film(read.film, stopped.film);

        scene.view.settings.threads = 2;
        RenderCallbacks resume;
        resume.resume_after_samples = read.samples_done;
        const RenderStats stats = render(*scene.world, scene.view, read.film, resume);
        EXPECT_EQ(stats.samples_per_pixel, 40u);
        expect_same_film(read.film, whole.film);
    }
}

TEST(Checkpoint, AResumeAfterACountThePassesNeverStopAtHasTheBitsOfOneThatNeverStopped) {
    // A checkpoint of a glint whose passes were 1, 2, 4, … stopped after 1, 3 or 7 samples, where today's
    // passes never stop: made here by a render of that many samples (sobol's sample i is the same
    // whatever the count), then resumed to 40.
    Scene scene = test::scene_from_text(kScene);
    const Checkpoint whole = render_until(scene, 2, 0);
    for (const std::uint32_t stopped_after : {1u, 3u, 7u}) {
        RenderFlags fewer;
        fewer.samples_per_pixel = stopped_after;
        Film film = test::render_film(test::scene_from_text(kScene, fewer));
        ASSERT_EQ(film.raw_pixel(10, 7).count, stopped_after);
        RenderCallbacks resume;
        resume.resume_after_samples = stopped_after;
        const RenderStats stats = render(*scene.world, scene.view, film, resume);
        EXPECT_EQ(stats.samples_per_pixel, 40u);
        expect_same_film(film, whole.film);
    }
}

TEST(Checkpoint, ResumingFromTheWrongSampleCountGivesAnotherImage) {
    // The test above could pass if resuming ignored the film; here a checkpoint claims one sample fewer
    // than its film holds, and the resumed film must then differ (a sample is taken twice).
    Scene scene = test::scene_from_text(kScene);
    const Checkpoint whole = render_until(scene, 2, 0);
    Checkpoint stopped = render_until(scene, 2, 8);
    RenderCallbacks resume;
    resume.resume_after_samples = stopped.samples_done - 1;
    render(*scene.world, scene.view, stopped.film, resume);
    EXPECT_NE(stopped.film.raw_pixel(10, 7).count, whole.film.raw_pixel(10, 7).count);
}

std::string decode_error(const std::vector<unsigned char>& bytes) {
    try {
        decode_checkpoint(bytes, "bad.ckpt");
    } catch (const CheckpointError& e) {
        return e.what();
    }
    return "no error";
}

template <typename T>
void poke(std::vector<unsigned char>& bytes, std::size_t offset, T value) {
    std::memcpy(bytes.data() + offset, &value, sizeof(T));
}

TEST(Checkpoint, ADamagedFileIsRefusedWithWhatIsWrong) {
    Checkpoint small;
    small.samples_done = 2;
    small.samples_asked = 8;
    small.film = Film(3, 2);
    small.film.add_sample(1, 1, Rgb(0.5, 0.25, 1));
    small.film.add_sample(1, 1, Rgb(0.5, 0.25, 1));
    const std::vector<unsigned char> good = encode_checkpoint(small);
    ASSERT_EQ(good.size(), 36u + 6 * 40u);
    EXPECT_EQ(decode_checkpoint(good, "good.ckpt").film.raw_pixel(1, 1).count, 2u);

    auto bytes = good;
    bytes[0] = 'X';
    EXPECT_NE(decode_error(bytes).find("bad.ckpt: error: not a glint checkpoint"), std::string::npos);
    EXPECT_NE(decode_error({good.begin(), good.begin() + 20}).find("not a glint checkpoint"),
              std::string::npos);
    bytes = good;
    poke<std::uint32_t>(bytes, 8, 7);
    EXPECT_NE(decode_error(bytes).find("checkpoint format 7"), std::string::npos);
    bytes = good;
    poke<std::uint32_t>(bytes, 20, 40000);  // width beyond the limit, before any allocation
    EXPECT_NE(decode_error(bytes).find("image size 40000 x 2"), std::string::npos);
    bytes = good;
    poke<std::uint32_t>(bytes, 20, 20000);
    poke<std::uint32_t>(bytes, 24, 20000);  // 4·10⁸ pixels: each side allowed, the area not
    EXPECT_NE(decode_error(bytes).find("outside"), std::string::npos);
    bytes = good;
    poke<std::uint32_t>(bytes, 28, 8);  // done = asked: nothing to resume
    EXPECT_NE(decode_error(bytes).find("8 of 8 samples"), std::string::npos);
    bytes = good;
    bytes.pop_back();
    EXPECT_NE(decode_error(bytes).find("275 bytes long; a 3 x 2 checkpoint has 276"), std::string::npos);
    bytes = good;
    poke<double>(bytes, 36 + 4 * 40, std::numeric_limits<double>::quiet_NaN());  // pixel (1, 1)'s red
    EXPECT_NE(decode_error(bytes).find("pixel (1, 1) at byte 196"), std::string::npos) << decode_error(bytes);
    bytes = good;
    poke<double>(bytes, 36 + 4 * 40 + 24, -1.0);  // a negative sum of squares
    EXPECT_NE(decode_error(bytes).find("pixel (1, 1) at byte 196"), std::string::npos);
    bytes = good;
    poke<std::uint64_t>(bytes, 36 + 4 * 40 + 32, 3);  // 3 samples in a 2-sample checkpoint
    EXPECT_NE(decode_error(bytes).find("more than 2 samples"), std::string::npos);
}

TEST(Checkpoint, OneOfAnotherRenderIsRefused) {
    Checkpoint c;
    c.scene_fingerprint = 7;
    c.samples_done = 1;
    c.samples_asked = 4;
    c.film = Film(5, 4);
    EXPECT_NO_THROW(check_checkpoint_matches(c, "c.ckpt", 7, 5, 4, 4));
    const auto message = [&](std::uint64_t fingerprint, int w, int h, std::uint32_t spp) -> std::string {
        try {
            check_checkpoint_matches(c, "c.ckpt", fingerprint, w, h, spp);
        } catch (const CheckpointError& e) {
            return e.what();
        }
        return "no error";
    };
    EXPECT_NE(message(8, 5, 4, 4).find("c.ckpt: error: the checkpoint is of another render"),
              std::string::npos);
    EXPECT_NE(message(7, 6, 4, 4).find("5 x 4 pixels; this render is 6 x 4"), std::string::npos);
    EXPECT_NE(message(7, 5, 4, 16).find("asks 4 samples per pixel; this one 16"), std::string::npos);
}

}  // namespace
}  // namespace glint
