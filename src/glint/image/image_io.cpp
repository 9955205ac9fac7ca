#include "glint/image/image_io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstring>

namespace glint {

namespace test_hooks {
void (*after_temporary_file_written)(const std::filesystem::path& temporary) = nullptr;
}  // namespace test_hooks

std::optional<ImageFormat> image_format_for(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".png") {
        return ImageFormat::Png;
    }
    if (ext == ".pfm") {
        return ImageFormat::Pfm;
    }
    if (ext == ".exr") {
        return ImageFormat::Exr;
    }
    return std::nullopt;
}

std::string supported_image_extensions() {
    return ".png, .pfm, .exr";
}

unsigned char linear_to_srgb8(float linear) {
    const double c =
        std::clamp(static_cast<double>(linear), 0.0, 1.0);  // NaN is never written: the film counts it
    const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return static_cast<unsigned char>(std::lround(encoded * 255.0));
}

namespace {

// The temporary files being written right now, kept where a signal handler can read them: a fixed array
// of fixed buffers (no allocation, no lock), each guarded by a sequence number as a seqlock. A writer
// makes the number odd, changes the slot, makes it even again; the handler copies a slot's path and uses
// it only if the number was even and unchanged across the copy, so it never acts on a half-written path
// (the handler may interrupt the very thread that is writing the slot). The path is stored as atomic
// chars so that those concurrent reads are well defined.
constexpr int kPendingSlots = 16;  // files written at once; more are written unregistered
constexpr std::size_t kPendingPathBytes = PATH_MAX;

struct PendingSlot {
    std::atomic<bool> claimed{false};     // owned by a writer (only writers touch this)
    std::atomic<unsigned> sequence{0};    // odd while the slot changes
    std::atomic<bool> registered{false};  // `path` names a temporary file that may exist
    std::array<std::atomic<char>, kPendingPathBytes> path{};
};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<unsigned>::is_always_lock_free &&
                  std::atomic<char>::is_always_lock_free,
              "a signal handler may only use lock-free atomics");

std::array<PendingSlot, kPendingSlots> g_pending_slots;

// Registers a temporary file's path for its lifetime: from before the file is created until after it
// has been renamed or removed.
class PendingTemporaryFile {
  public:
    explicit PendingTemporaryFile(const std::string& path) {
        if (path.size() >= kPendingPathBytes) {
            return;  // creating it will fail with ENAMETOOLONG anyway
        }
        for (PendingSlot& slot : g_pending_slots) {
            bool expected = false;
            if (slot.claimed.compare_exchange_strong(expected, true, std::memory_order_acquire)) {
                slot_ = &slot;
                break;
            }
        }
        if (!slot_) {
            return;
        }
        begin_change();
        for (std::size_t i = 0; i <= path.size(); ++i) {  // with the terminating '\0'
            slot_->path[i].store(path.c_str()[i], std::memory_order_relaxed);
        }
        slot_->registered.store(true, std::memory_order_relaxed);
        end_change();
    }
    ~PendingTemporaryFile() {
        if (slot_) {
            begin_change();
            slot_->registered.store(false, std::memory_order_relaxed);
            end_change();
            slot_->claimed.store(false, std::memory_order_release);
        }
    }
    PendingTemporaryFile(const PendingTemporaryFile&) = delete;
    PendingTemporaryFile& operator=(const PendingTemporaryFile&) = delete;

  private:
    void begin_change() {
        slot_->sequence.fetch_add(1, std::memory_order_relaxed);
        std::atomic_thread_fence(std::memory_order_release);
    }
    void end_change() { slot_->sequence.fetch_add(1, std::memory_order_release); }

    PendingSlot* slot_ = nullptr;
};

[[noreturn]] void write_failed(const std::filesystem::path& path, const std::string& why) {
    throw ImageWriteError("cannot write '" + path.string() + "': " + why);
}

std::filesystem::path folder_of(const std::filesystem::path& path) {
    return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

// A fresh name beside `path` for its temporary file: hidden, recognisable, unique to this process and
// call, and within NAME_MAX whatever the length of the target's own name.
std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
    static std::atomic<unsigned> counter{0};
    const std::string name = path.filename().string().substr(0, 200);
    return folder_of(path) / ("." + name + ".glint-tmp-" + std::to_string(::getpid()) + "-" +
                              std::to_string(counter.fetch_add(1)));
}

// Creates a new temporary file for `path`, registered as pending. Returns its descriptor, or −1 with
// errno set.
int create_temporary(const std::filesystem::path& path, std::filesystem::path& temporary,
                     std::optional<PendingTemporaryFile>& pending) {
    for (int attempt = 0; attempt < 100; ++attempt) {
        temporary = temporary_path_for(path);
        pending.emplace(temporary.string());
        // O_EXCL: never reuse a file that is already there (a stale temporary, or a link planted there).
        const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST) {
            return fd;
        }
        pending.reset();
    }
    errno = EEXIST;
    return -1;
}

bool write_all(int fd, const unsigned char* data, std::size_t size) {
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            if (n == 0) {
                errno = EIO;
            }
            return false;
        }
        data += n;
        size -= static_cast<std::size_t>(n);
    }
    return true;
}

}  // namespace

void remove_pending_temporary_files() noexcept {
    // Async-signal-safe: lock-free atomic loads, fences, a stack buffer and unlink(2), which POSIX lists
    // as async-signal-safe. No allocation, no locks, no errno left changed.
    const int saved_errno = errno;
    char path[kPendingPathBytes];
    for (PendingSlot& slot : g_pending_slots) {
        const unsigned before = slot.sequence.load(std::memory_order_acquire);
        if (before % 2 != 0 || !slot.registered.load(std::memory_order_relaxed)) {
            continue;  // free, or changing under an interrupted writer: no file to remove yet or any more
        }
        for (std::size_t i = 0; i < kPendingPathBytes; ++i) {
            path[i] = slot.path[i].load(std::memory_order_relaxed);
            if (path[i] == '\0') {
                break;
            }
        }
        path[kPendingPathBytes - 1] = '\0';
        std::atomic_thread_fence(std::memory_order_acquire);
        if (slot.sequence.load(std::memory_order_relaxed) == before) {
            ::unlink(path);
        }
    }
    errno = saved_errno;
}

void write_file_atomically(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
    std::filesystem::path temporary;
    std::optional<PendingTemporaryFile> pending;
    const int fd = create_temporary(path, temporary, pending);
    if (fd < 0) {
        write_failed(path, std::strerror(errno));
    }
    // Written, then flushed to the disk before the rename: otherwise a power cut soon after could leave the
    // new name pointing at a file whose data never reached the disk (an empty or partial image).
    const bool written = write_all(fd, bytes.data(), bytes.size()) && ::fsync(fd) == 0;
    const int write_errno = errno;
    const bool closed = ::close(fd) == 0;
    const int close_errno = errno;
    if (!written || !closed) {
        ::unlink(temporary.c_str());
        write_failed(path, std::strerror(written ? close_errno : write_errno));
    }
    if (test_hooks::after_temporary_file_written) {
        test_hooks::after_temporary_file_written(temporary);
    }
    if (::rename(temporary.c_str(), path.c_str()) != 0) {
        const int rename_errno = errno;
        ::unlink(temporary.c_str());
        write_failed(path, std::strerror(rename_errno));
    }
    pending.reset();
    // The rename itself is durable once the folder is flushed. Best effort: some file systems refuse
    // fsync on a folder, and the image is complete either way.
    const int folder = ::open(folder_of(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (folder >= 0) {
        ::fsync(folder);
        ::close(folder);
    }
}

void check_output_path(const std::filesystem::path& path) {
    if (!image_format_for(path)) {
        write_failed(path, "unknown image format (use " + supported_image_extensions() + ")");
    }
    const std::filesystem::path folder = folder_of(path);
    const auto too_long = [&] {
        long name_max = ::pathconf(folder.c_str(), _PC_NAME_MAX);
        name_max = name_max > 0 ? name_max : NAME_MAX;
        for (const auto& part : path) {
            if (static_cast<long>(part.native().size()) > name_max) {
                write_failed(path, "the name '" + part.native().substr(0, 40) + "...' is " +
                                       std::to_string(part.native().size()) + " bytes long; the limit is " +
                                       std::to_string(name_max) + " (NAME_MAX)");
            }
        }
        write_failed(path, "the path is " + std::to_string(path.native().size()) +
                               " bytes long, too long for the system (PATH_MAX is " +
                               std::to_string(PATH_MAX) + ")");
    };
    struct stat status {};
    if (::stat(folder.c_str(), &status) != 0) {
        const int error = errno;
        if (error == ENAMETOOLONG) {
            too_long();
        }
        if (error == ENOENT) {
            write_failed(path, "the folder '" + folder.string() + "' does not exist");
        }
        if (error == ENOTDIR) {
            write_failed(path,
                         "the folder '" + folder.string() + "' does not exist (part of its path is a file)");
        }
        write_failed(path, "cannot reach the folder '" + folder.string() + "': " + std::strerror(error));
    }
    if (!S_ISDIR(status.st_mode)) {
        write_failed(path, "'" + folder.string() + "' is not a folder");
    }
    if (::stat(path.c_str(), &status) == 0) {
        if (S_ISDIR(status.st_mode)) {
            write_failed(path, "it is a folder");
        }
        if (!S_ISREG(status.st_mode)) {
            write_failed(path, "it exists and is not a regular file");
        }
    } else if (errno == ENAMETOOLONG) {
        too_long();
    }
    // Only creating a file tells whether the folder takes one: permission bits do not (root ignores
    // them; read-only mounts, ACLs and quotas are not in them). The probe is the writer's own
    // temporary file, so its name is tested too.
    std::filesystem::path probe;
    std::optional<PendingTemporaryFile> pending;
    const int fd = create_temporary(path, probe, pending);
    if (fd < 0) {
        const int error = errno;
        if (error == ENAMETOOLONG) {
            too_long();
        }
        if (error == EACCES || error == EPERM) {
            write_failed(
                path, "the folder '" + folder.string() + "' is not writable (" + std::strerror(error) + ")");
        }
        if (error == EROFS) {
            write_failed(path, "the folder '" + folder.string() + "' is on a read-only file system");
        }
        write_failed(path, "cannot create a file in '" + folder.string() + "': " + std::strerror(error));
    }
    ::close(fd);
    ::unlink(probe.c_str());
}

void write_image(const Image& image, const std::filesystem::path& path, const DisplayTransform& display) {
    const std::optional<ImageFormat> format = image_format_for(path);
    if (!format) {
        write_failed(path, "unknown image format (use " + supported_image_extensions() + ")");
    }
    switch (*format) {
        case ImageFormat::Png: {
            const bool as_is =
                display.exposure == 0 && display.curve == ToneCurve::Clamp;  // encode_png clamps
            write_file_atomically(path, encode_png(as_is ? image : to_display(image, display)));
            break;
        }
        case ImageFormat::Pfm:
            write_file_atomically(path, encode_pfm(image));
            break;
        case ImageFormat::Exr:
            write_file_atomically(path, encode_exr(image));
            break;
    }
}

}  // namespace glint
