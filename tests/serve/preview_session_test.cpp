// What an edit in `glint serve` rebuilds: only what it touches. A camera or render-settings edit keeps
// the built world (no mesh read, no BVH built); a material edit keeps the shapes and their accelerator;
// an edit that changes nothing keeps the accumulation. Measured on a mesh of 262 144 triangles, whose
// file is watched with inotify. (How fast the first frame comes is measured by bench/serve_edit.cpp.)
#include "glint/serve/preview_session.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "generated_meshes.hpp"
#include "serve/open_watch.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

// Waits (up to a minute, for sanitizer builds) for a frame of `generation`.
std::shared_ptr<const PreviewFrame> frame_of(const PreviewSession& session, std::uint64_t generation) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    std::uint64_t seen = 0;
    while (std::chrono::steady_clock::now() < deadline) {
        const auto frame = session.wait_for_frame(seen, std::chrono::milliseconds(100));
        if (frame && frame->generation == generation) {
            return frame;
        }
        seen = frame ? frame->id : 0;
    }
    return nullptr;
}

SceneEdit edit(std::vector<std::string> path, const std::string& value) {
    Node node;
    node.kind = Node::Kind::Scalar;
    node.scalar = value;
    return {std::move(path), node};
}

class PreviewEdits : public ::testing::Test {
  protected:
    void SetUp() override {
        desc_ = parse_scene_text(test::large_mesh_scene(dir_.path()), (dir_ / "scene.yaml").string(),
                                 dir_.path());
        session_ = std::make_unique<PreviewSession>(desc_, "scene.yaml");
        ASSERT_TRUE(frame_of(*session_, 1));
        watch_ = std::make_unique<test::OpenWatch>(dir_.path());
    }
    test::TempDir dir_;
    SceneDesc desc_;
    std::unique_ptr<PreviewSession> session_;
    std::unique_ptr<test::OpenWatch> watch_;
};

TEST_F(PreviewEdits, ACameraEditKeepsTheWorldAndReadsNoFile) {
    const std::shared_ptr<const World> before = session_->world();
    ASSERT_EQ(before->shapes.size(), 1u);
    const std::uint64_t generation = session_->apply({edit({"camera", "fov"}, "35")});
    EXPECT_EQ(generation, 2u);
    EXPECT_EQ(session_->world(), before);  // the same object: nothing rebuilt
    const auto frame = frame_of(*session_, generation);
    ASSERT_TRUE(frame);
    EXPECT_EQ(watch_->opened(), std::vector<std::string>{});
    // Render settings too.
    EXPECT_EQ(session_->apply({edit({"render", "samples"}, "9")}), 3u);
    EXPECT_EQ(session_->apply({edit({"render", "integrator"}, "path")}), 4u);
    // The pixel filter is a render setting: the view is rebuilt with it, and it renders.
    EXPECT_EQ(session_->apply({edit({"render", "filter"}, "tent")}), 5u);
    EXPECT_EQ(session_->state().settings.filter.type, PixelFilterType::tent);
    EXPECT_TRUE(frame_of(*session_, 5u));
    EXPECT_EQ(session_->world(), before);
    EXPECT_EQ(watch_->opened(), std::vector<std::string>{});
}

TEST_F(PreviewEdits, AMaterialEditRebuildsMaterialsButNotTheShapesOrTheirBvh) {
    const std::shared_ptr<const World> before = session_->world();
    const std::uint64_t generation = session_->apply({edit({"materials", "clay", "albedo"}, "0.3")});
    const std::shared_ptr<const World> after = session_->world();
    EXPECT_NE(after, before);
    ASSERT_EQ(after->shapes.size(), 1u);
    EXPECT_EQ(after->shapes[0], before->shapes[0]);
    EXPECT_EQ(after->accelerator, before->accelerator);
    EXPECT_NE(after->materials[0].get(), before->materials[0].get());
    ASSERT_TRUE(frame_of(*session_, generation));
    EXPECT_EQ(watch_->opened(), std::vector<std::string>{});
}

TEST_F(PreviewEdits, AnAcceleratorEditRebuildsTheAcceleratorOverTheSameShapes) {
    const std::shared_ptr<const World> before = session_->world();
    session_->apply({edit({"render", "accelerator"}, "list")});
    const std::shared_ptr<const World> after = session_->world();
    EXPECT_EQ(after->shapes[0], before->shapes[0]);
    EXPECT_NE(after->accelerator, before->accelerator);
    EXPECT_EQ(watch_->opened(), std::vector<std::string>{});
}

TEST_F(PreviewEdits, AnEditThatChangesNothingKeepsTheAccumulation) {
    const auto first = frame_of(*session_, 1);
    const std::shared_ptr<const World> before = session_->world();
    EXPECT_EQ(session_->apply({edit({"camera", "fov"}, "50")}), 1u);  // the value it has
    EXPECT_EQ(session_->state().generation, 1u);
    EXPECT_EQ(session_->world(), before);
    const auto later = session_->wait_for_frame(0, std::chrono::milliseconds(10));
    ASSERT_TRUE(later);
    EXPECT_EQ(later->generation, 1u);
    EXPECT_GE(later->id, first->id);
}

}  // namespace
}  // namespace glint

namespace glint {
namespace {

TEST_F(PreviewEdits, ExportWritesAbsolutePathsSoTheSceneRendersFromAnyFolder) {
    const std::string yaml = session_->export_yaml();
    const std::string absolute =
        (std::filesystem::absolute(dir_.path()) / "torus.ply").lexically_normal().generic_string();
    EXPECT_NE(yaml.find("file: " + absolute), std::string::npos) << yaml;
    // Read as if saved somewhere else entirely: it builds, with the same mesh.
    const Scene exported =
        build_scene(parse_scene_text(yaml, "/somewhere/else/exported.yaml", "/somewhere/else"));
    EXPECT_EQ(exported.world->shapes.size(), 1u);
    // The scene in the session keeps its own relative path.
    EXPECT_NE(session_->state().yaml.find("file: torus.ply"), std::string::npos);
}

}  // namespace
}  // namespace glint

namespace glint {
namespace {

TEST(PreviewContinuous, RefinesPastTheTargetUntilToldToStopWithTheBitsOfThatManySamples) {
    const std::string text =
        "render: {width: 16, height: 12, samples: 4}\ncamera: {eye: [0, 0, 4], look_at: [0, 0, 0], fov: 40}\n"
        "objects:\n  - {type: sphere, radius: 1}\nlights:\n  - {type: point, position: [2, 2, 2], intensity: "
        "10}\n";
    PreviewSession session(parse_scene_text(text, "c.yaml", "."), "c.yaml");
    EXPECT_TRUE(session.state().extendable);
    session.set_continuous(true);
    // Wait for a frame past the scene's 4 samples.
    std::shared_ptr<const PreviewFrame> frame;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    std::uint64_t seen = 0;
    while (std::chrono::steady_clock::now() < deadline) {
        frame = session.wait_for_frame(seen, std::chrono::milliseconds(100));
        if (frame && frame->samples > 16) {
            break;
        }
        seen = frame ? frame->id : 0;
    }
    ASSERT_TRUE(frame && frame->samples > 16);
    session.set_continuous(false);
    // What it shows is a render of that many samples, bit for bit.
    RenderFlags flags;
    flags.samples_per_pixel = frame->samples;
    const Film reference = test::render_film(build_scene(parse_scene_text(text, "c.yaml", "."), flags));
    EXPECT_EQ(frame->linear->rgb, reference.to_image().rgb);
    // Stopped: the render settles at the target it had reached (or the one it had just doubled to when
    // told), and then no frame follows.
    std::shared_ptr<const PreviewFrame> last = session.latest_frame();
    for (std::shared_ptr<const PreviewFrame> next;
         (next = session.wait_for_frame(last->id, std::chrono::seconds(2)))->id != last->id;) {
        last = next;
    }
    EXPECT_FALSE(session.continuous());
    EXPECT_EQ(last->samples, last->target);
    EXPECT_LE(last->target, 2 * frame->target);
    session.stop();
}

}  // namespace
}  // namespace glint
