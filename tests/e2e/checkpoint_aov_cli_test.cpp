// `glint render --checkpoint/--resume` and `--aov` from the command line: a render stopped by its time
// limit and resumed gives the bytes of one that never stopped; a checkpoint of another render is
// refused; the AOVs come out as EXR layers (read back channel by channel) and as PFM files, with the
// values a plane seen square-on must give.
#include <gtest/gtest.h>
#include <tinyexr.h>

#include <cstdlib>
#include <fstream>
#include <map>

#include "glint/image/image_io.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

const char* kScene =
    "render: {width: 32, height: 24, samples: 40, integrator: path}\n"
    "camera: {eye: [0, 1, 5], look_at: [0, 0, 0], fov: 40}\n"
    "objects:\n  - {type: sphere, radius: 0.7, material: {type: dielectric, ior: 1.5}}\n"
    "  - {type: plane, point: [0, -0.7, 0], normal: [0, 1, 0]}\n"
    "lights:\n  - {type: environment, radiance: [0.5, 0.7, 1.0]}\n";

TEST(CheckpointCli, AStoppedRenderResumedGivesTheBytesOfOneThatNeverStopped) {
    test::TempDir dir;
    dir.write("s.yaml", kScene);
    const std::string scene = "render '" + (dir / "s.yaml").string() + "' ";
    ASSERT_EQ(test::run_glint(scene + "-q --threads 2 -o '" + (dir / "whole.pfm").string() + "'").exit_code,
              0);
    const std::string checkpoint = (dir / "s.ckpt").string();
    // A limit crossed by the first pass: the render stops after 2 samples and leaves the checkpoint.
    const auto stopped = test::run_glint(scene + "--threads 1 --time-limit 1e-9 --checkpoint '" + checkpoint +
                                         "' -o '" + (dir / "stopped.pfm").string() + "'");
    ASSERT_EQ(stopped.exit_code, 0) << stopped.output;
    EXPECT_NE(stopped.output.find("holds 2 of 40 samples"), std::string::npos) << stopped.output;
    ASSERT_TRUE(std::filesystem::exists(checkpoint));

    // Another render's checkpoint is refused, and nothing is written.
    const auto other = test::run_glint(scene + "--seed 9 --resume '" + checkpoint + "' -o '" +
                                       (dir / "other.pfm").string() + "'");
    EXPECT_EQ(other.exit_code, 2);
    EXPECT_NE(other.output.find("the checkpoint is of another render"), std::string::npos) << other.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "other.pfm"));

    const auto resumed = test::run_glint(scene + "--threads 2 --checkpoint '" + checkpoint + "' --resume '" +
                                         checkpoint + "' -o '" + (dir / "resumed.pfm").string() + "'");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    EXPECT_NE(resumed.output.find("resuming"), std::string::npos);
    EXPECT_EQ(read_bytes(dir / "resumed.pfm"), read_bytes(dir / "whole.pfm"));
    EXPECT_FALSE(std::filesystem::exists(checkpoint));  // the image is complete: no longer needed
    EXPECT_NE(read_bytes(dir / "stopped.pfm"), read_bytes(dir / "whole.pfm"));

    // A damaged checkpoint: exit 2 with the file named.
    dir.write("bad.ckpt", "GLINTCKP and then nothing a checkpoint should hold");
    const auto bad = test::run_glint(scene + "--resume '" + (dir / "bad.ckpt").string() + "' -o '" +
                                     (dir / "bad.pfm").string() + "'");
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.output.find("bad.ckpt: it is 50 bytes long; a checkpoint of this 32 x 24 render has 30756"),
              std::string::npos)
        << bad.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.pfm"));
}

// The float values of the named channels of an EXR file, read with tinyexr's own API.
std::map<std::string, std::vector<float>> exr_channels(const std::filesystem::path& path) {
    EXRVersion version;
    EXRHeader header;
    EXRImage image;
    const char* error = nullptr;
    InitEXRHeader(&header);
    InitEXRImage(&image);
    std::map<std::string, std::vector<float>> channels;
    if (ParseEXRVersionFromFile(&version, path.c_str()) != TINYEXR_SUCCESS ||
        ParseEXRHeaderFromFile(&header, &version, path.c_str(), &error) != TINYEXR_SUCCESS ||
        LoadEXRImageFromFile(&image, &header, path.c_str(), &error) != TINYEXR_SUCCESS) {
        FreeEXRErrorMessage(error);
        return channels;
    }
    for (int c = 0; c < header.num_channels; ++c) {
        const auto* values = reinterpret_cast<const float*>(image.images[c]);
        channels[header.channels[c].name] =
            std::vector<float>(values, values + static_cast<std::size_t>(image.width) * image.height);
    }
    FreeEXRImage(&image);
    FreeEXRHeader(&header);
    return channels;
}

TEST(AovCli, LayersOfAnExrAndFilesBesideAPfmHoldTheKnownValues) {
    test::TempDir dir;
    // A plane of albedo (0.25, 0.5, 0.75) seen square-on from 5 units by an orthographic camera.
    dir.write("plane.yaml",
              "render: {width: 8, height: 6, samples: 4}\n"
              "camera: {type: orthographic, eye: [0, 0, 5], look_at: [0, 0, 0], height: 2}\n"
              "objects:\n  - {type: plane, point: [0, 0, 0], normal: [0, 0, 1], material: {type: matte, "
              "albedo: [0.25, 0.5, 0.75]}}\n"
              "lights:\n  - {type: point, position: [0, 0, 3], intensity: 5}\n");
    const std::string scene = "render '" + (dir / "plane.yaml").string() + "' -q ";
    ASSERT_EQ(test::run_glint(scene + "-o '" + (dir / "plain.exr").string() + "'").exit_code, 0);
    const auto with = test::run_glint(scene + "--aov albedo,normal,depth,spp,variance -o '" +
                                      (dir / "aov.exr").string() + "'");
    ASSERT_EQ(with.exit_code, 0) << with.output;
    const auto channels = exr_channels(dir / "aov.exr");
    for (const char* name : {"R", "G", "B", "albedo.R", "albedo.G", "albedo.B", "normal.X", "normal.Y",
                             "normal.Z", "depth.Z", "spp.Y", "variance.Y"}) {
        ASSERT_EQ(channels.count(name), 1u) << name;
        ASSERT_EQ(channels.at(name).size(), 48u) << name;
    }
    for (std::size_t i = 0; i < 48; ++i) {
        EXPECT_FLOAT_EQ(channels.at("albedo.R")[i], 0.25f);
        EXPECT_FLOAT_EQ(channels.at("albedo.B")[i], 0.75f);
        EXPECT_FLOAT_EQ(channels.at("normal.Z")[i], 1.0f);
        EXPECT_NEAR(channels.at("depth.Z")[i], 5.0f, 1e-5);
        EXPECT_EQ(channels.at("spp.Y")[i], 4.0f);
    }
    // The image itself is the one rendered without AOVs, and the file says what made it.
    const ExrFile plain = read_exr(dir / "plain.exr");
    const ExrFile layered = read_exr(dir / "aov.exr");
    EXPECT_EQ(layered.image.rgb, plain.image.rgb);
    EXPECT_EQ(layered.attributes.at("glintSpp"), "4");
    EXPECT_EQ(layered.attributes.at("glintSeed"), "1");  // the default seed
    EXPECT_NE(layered.attributes.at("glintCamera").find("orthographic"), std::string::npos);
    EXPECT_EQ(layered.attributes.at("glintVersion"), GLINT_VERSION);

    ASSERT_EQ(test::run_glint(scene + "--aov albedo,depth -o '" + (dir / "aov.pfm").string() + "'").exit_code,
              0);
    const Image albedo = read_pfm(dir / "aov.albedo.pfm");
    EXPECT_FLOAT_EQ(albedo.pixel(3, 3)[1], 0.5f);
    const Image depth = read_pfm(dir / "aov.depth.pfm");  // grey PFM: Z in all three channels once read
    EXPECT_NEAR(depth.pixel(3, 3)[0], 5.0f, 1e-5);
    EXPECT_FALSE(std::filesystem::exists(dir / "aov.normal.pfm"));
}

}  // namespace
}  // namespace glint
