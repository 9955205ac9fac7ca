#include "glint/image/image_io.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <climits>
#include <csignal>

#include "test_util.hpp"

namespace glint {
namespace {

Image small_image_for_io() {
    Image image(3, 2);
    for (size_t i = 0; i < image.rgb.size(); ++i) {
        image.rgb[i] = 0.25f * static_cast<float>(i);
    }
    return image;
}

TEST(ImageIo, PfmRoundTripsExactly) {
    test::TempDir dir;
    Image image(3, 2);
    for (size_t i = 0; i < image.rgb.size(); ++i) {
        image.rgb[i] = 0.1f * static_cast<float>(i) + 1e-7f;
    }
    image.pixel(2, 1)[0] = 1234.5f;  // radiance above 1 is kept
    write_image(image, dir / "x.pfm");
    const Image back = read_pfm(dir / "x.pfm");
    EXPECT_EQ(back.width, 3);
    EXPECT_EQ(back.height, 2);
    EXPECT_EQ(back.rgb, image.rgb);
}

TEST(ImageIo, SrgbEncodingOfKnownValues) {
    EXPECT_EQ(linear_to_srgb8(0.0f), 0);
    EXPECT_EQ(linear_to_srgb8(1.0f), 255);
    EXPECT_EQ(linear_to_srgb8(7.0f), 255);  // clamped
    EXPECT_EQ(linear_to_srgb8(-1.0f), 0);   // clamped
    EXPECT_EQ(linear_to_srgb8(0.5f), 188);  // 1.055 · 0.5^(1/2.4) − 0.055 = 0.7354
    EXPECT_EQ(linear_to_srgb8(0.002f), 7);  // linear segment: 12.92 · 0.002 · 255 = 6.6
}

TEST(ImageIo, FormatsFollowTheExtension) {
    EXPECT_EQ(image_format_for("a.PNG"), ImageFormat::Png);
    EXPECT_EQ(image_format_for("dir/a.exr"), ImageFormat::Exr);
    EXPECT_EQ(image_format_for("a.pfm"), ImageFormat::Pfm);
    EXPECT_FALSE(image_format_for("a.jpg"));
    EXPECT_FALSE(image_format_for("png"));
}

TEST(ImageIo, EncodersProduceTheirMagicNumbers) {
    Image image(4, 4);
    const auto png = encode_png(image);
    ASSERT_GT(png.size(), 8u);
    EXPECT_EQ(png[1], 'P');
    EXPECT_EQ(png[2], 'N');
    const auto exr = encode_exr(image);
    ASSERT_GT(exr.size(), 4u);
    EXPECT_EQ(exr[0], 0x76);  // OpenEXR magic 20000630 = 0x762f3101, little-endian
    EXPECT_EQ(exr[1], 0x2f);
}

TEST(ImageIo, AtomicWriteLeavesNoTemporaryAndReplacesTheOldFile) {
    test::TempDir dir;
    dir.write("x.png", "old contents");
    Image image(2, 2);
    write_image(image, dir / "x.png");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
    EXPECT_NE(std::filesystem::file_size(dir / "x.png"), 12u);
}

TEST(ImageIo, UnwritableTargetThrowsAndLeavesNothing) {
    Image image(2, 2);
    EXPECT_THROW(write_image(image, "/nonexistent-dir/x.png"), ImageWriteError);
    // A folder in the way of the file: the temporary is written, the rename fails, nothing is left.
    test::TempDir dir;
    std::filesystem::create_directories(dir / "x.png" / "inside");
    EXPECT_THROW(write_image(image, dir / "x.png"), ImageWriteError);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
}

size_t entries_in(const std::filesystem::path& folder) {
    return static_cast<size_t>(std::distance(std::filesystem::directory_iterator(folder), {}));
}

// The hook below runs inside write_file_atomically, between the complete temporary file and the rename.
std::filesystem::path g_seen_temporary;
bool g_temporary_existed = false;
bool g_temporary_removed = false;

TEST(ImageIo, PendingTemporaryFilesAreRemovedOnRequest) {
    test::TempDir dir;
    test_hooks::after_temporary_file_written = [](const std::filesystem::path& temporary) {
        g_seen_temporary = temporary;
        g_temporary_existed = std::filesystem::exists(temporary);
        remove_pending_temporary_files();  // as a SIGINT handler would, mid-write
        g_temporary_removed = !std::filesystem::exists(temporary);
    };
    // With its temporary file gone, the rename fails: an error, and no file at all.
    EXPECT_THROW(write_image(small_image_for_io(), dir / "x.pfm"), ImageWriteError);
    test_hooks::after_temporary_file_written = nullptr;
    EXPECT_EQ(g_seen_temporary.parent_path(), dir.path());
    EXPECT_TRUE(g_temporary_existed);
    EXPECT_TRUE(g_temporary_removed);
    EXPECT_EQ(entries_in(dir.path()), 0u);
    // Once written, a file is no longer pending: the call removes nothing.
    write_image(small_image_for_io(), dir / "x.pfm");
    remove_pending_temporary_files();
    EXPECT_TRUE(std::filesystem::exists(dir / "x.pfm"));
    EXPECT_EQ(entries_in(dir.path()), 1u);
}

extern "C" void remove_and_exit(int) {
    remove_pending_temporary_files();
    _exit(3);
}

TEST(ImageIoDeathTest, AProcessKilledMidWriteLeavesNoTemporaryFile) {
    // The real thing, in a child process: a SIGTERM handler that calls remove_pending_temporary_files,
    // and a SIGTERM that arrives while the image is being written.
    test::TempDir dir;
    const auto target = dir / "x.exr";
    EXPECT_EXIT(
        {
            std::signal(SIGTERM, remove_and_exit);
            test_hooks::after_temporary_file_written = [](const std::filesystem::path&) {
                std::raise(SIGTERM);
            };
            write_image(small_image_for_io(), target);
        },
        ::testing::ExitedWithCode(3), "");
    EXPECT_EQ(entries_in(dir.path()), 0u);
}

TEST(ImageIo, CheckOutputPathAcceptsAWritableFolderAndLeavesNothing) {
    test::TempDir dir;
    EXPECT_NO_THROW(check_output_path(dir / "out.png"));
    EXPECT_NO_THROW(check_output_path(dir / "OUT.EXR"));
    dir.write("existing.pfm", "old");
    EXPECT_NO_THROW(check_output_path(dir / "existing.pfm"));
    EXPECT_EQ(entries_in(dir.path()), 1u);
}

// Expects check_output_path to throw ImageWriteError naming the path and `reason`.
void expect_unwritable(const std::filesystem::path& path, const std::string& reason) {
    try {
        check_output_path(path);
        ADD_FAILURE() << path << " was accepted";
    } catch (const ImageWriteError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.rfind("cannot write '" + path.string() + "': ", 0), 0u) << message;
        EXPECT_NE(message.find(reason), std::string::npos) << "'" << reason << "' not in: " << message;
    }
}

TEST(ImageIo, CheckOutputPathExplainsWhyAPathCannotBeWritten) {
    test::TempDir dir;
    expect_unwritable(dir / "out.jpg", "unknown image format (use .png, .pfm, .exr)");
    expect_unwritable(dir / "png", "unknown image format");
    std::filesystem::create_directories(dir / "folder.png");
    expect_unwritable(dir / "folder.png", "it is a folder");
    expect_unwritable(dir / "missing" / "out.png",
                      "the folder '" + (dir / "missing").string() + "' does not exist");
    dir.write("file", "x");
    expect_unwritable(dir / "file" / "out.png", "'" + (dir / "file").string() + "' is not a folder");
    expect_unwritable(dir / "file" / "deeper" / "out.png", "(part of its path is a file)");
    const std::string long_name(300, 'n');
    expect_unwritable(dir / (long_name + ".png"), "is 304 bytes long; the limit is 255 (NAME_MAX)");
    std::filesystem::path long_path = dir.path();
    while (long_path.native().size() <= PATH_MAX) {
        long_path /= std::string(200, 'd');
    }
    expect_unwritable(long_path / "out.png", "too long");
    EXPECT_EQ(entries_in(dir.path()), 2u);  // folder.png and file: nothing left by the checks
}

TEST(ImageIo, CheckOutputPathFindsAFolderThatTakesNoFile) {
    // Permission bits do not stop root, so as root the folder is one of /sys, which refuses new files
    // to everyone; otherwise a folder of ours without write permission.
    test::TempDir dir;
    std::filesystem::path folder = dir / "read-only";
    if (::geteuid() == 0) {
        folder = "/sys";
        if (::access("/sys", F_OK) != 0) {
            GTEST_SKIP() << "running as root without /sys: no folder refuses a new file";
        }
    } else {
        std::filesystem::create_directories(folder);
        std::filesystem::permissions(folder,
                                     std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
    }
    try {
        check_output_path(folder / "out.png");
        ADD_FAILURE() << folder << " took a file";
    } catch (const ImageWriteError& e) {
        const std::string message = e.what();
        EXPECT_TRUE(message.find("is not writable") != std::string::npos ||
                    message.find("read-only file system") != std::string::npos)
            << message;
    }
    if (::geteuid() != 0) {
        std::filesystem::permissions(folder, std::filesystem::perms::owner_all);
        EXPECT_EQ(entries_in(folder), 0u);
    }
}

}  // namespace
}  // namespace glint
