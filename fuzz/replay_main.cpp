// The main() of a harness outside libFuzzer: runs LLVMFuzzerTestOneInput once on every file of the
// folders (and files) given, in name order, each in a child process of its own. ctest runs each harness this
// way over its seed corpus and its saved regressions (fuzz/CMakeLists.txt), so every build — g++ release, the
// sanitize preset — replays what the fuzzer once found, without clang or libFuzzer.
//
// A finding shows as a crash or abort of the child (a sanitizer's report, a failed check, an uncaught
// exception), a single allocation of 2 GiB or more (as libFuzzer's -malloc_limit_mb, see below), a peak
// of more than 2048 MB resident (-rss_limit_mb), or an input slower than kSlowSeconds: bad input must be
// refused within about a second (docs: the project's standards), and well within the fuzzer's -timeout of 10
// s under the sanitizers.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#if defined(__SANITIZE_ADDRESS__)  // g++ -fsanitize=address
#define GLINT_REPLAY_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)  // clang
#define GLINT_REPLAY_UNDER_ASAN 1
#endif
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

constexpr long kRssLimitMb = 2048;  // libFuzzer's -rss_limit_mb in fuzz/run.sh, checked on the child's peak

#if defined(GLINT_REPLAY_UNDER_ASAN)
constexpr bool kAddressSanitizer = true;
constexpr double kSlowSeconds = 10;  // libFuzzer's -timeout in fuzz/run.sh
constexpr unsigned kKillSeconds = 60;
#else
constexpr bool kAddressSanitizer = false;
constexpr double kSlowSeconds = 2;  // the seeds take milliseconds; 2 s leaves room for a loaded machine
constexpr unsigned kKillSeconds = 20;
#endif

// As the fuzzer's -rss_limit_mb=2048 would, stop an input that wants unbounded memory (many allocations
// each under the limit below) before it takes the machine's: without AddressSanitizer (which reserves
// terabytes of address space), cap the address space, so the allocation that crosses it fails.
void limit_memory() {
    if (kAddressSanitizer) {
        return;
    }
    constexpr rlim_t kLimit = rlim_t{4} << 30;  // the 2 GiB of data plus code, threads' stacks, TBB
    rlimit limit{kLimit, kLimit};
    if (setrlimit(RLIMIT_AS, &limit) != 0) {
        std::perror("setrlimit");
    }
}

}  // namespace

// libFuzzer stops an input that asks for 2048 MiB or more in one allocation (its -malloc_limit_mb,
// which follows -rss_limit_mb=2048): a size read from a file and not checked before allocating. The
// normal build does the same by interposing malloc, calloc and realloc on glibc's (operator new and
// every library call them), so such a regression fails here too, even where the allocation would
// have succeeded (overcommit) and the reader then failed politely. AddressSanitizer has its own
// malloc: under the sanitize preset its options say the same (over 2047 MiB in one allocation, or 3 GiB
// resident, is an error), built into the program so that a replay by hand behaves as under ctest.
#if defined(GLINT_REPLAY_UNDER_ASAN)
extern "C" const char* __asan_default_options() {
    return "max_allocation_size_mb=2047:hard_rss_limit_mb=3072";
}
#else
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);
}

namespace {

constexpr std::size_t kMallocLimitMiB = 2048;

[[noreturn]] void allocation_too_large(std::size_t size) {
    // No stdio: it may allocate. The size in decimal, by hand.
    char digits[24];
    int n = 0;
    do {
        digits[n++] = static_cast<char>('0' + size % 10);
        size /= 10;
    } while (size > 0);
    char message[96] = "replay: an allocation of ";
    std::size_t length = 25;
    while (n > 0) {
        message[length++] = digits[--n];
    }
    const char tail[] = " bytes, over the 2048 MiB limit: a finding\n";
    for (const char c : tail) {
        if (c != '\0') {
            message[length++] = c;
        }
    }
    (void)!::write(STDERR_FILENO, message, length);
    std::abort();
}

void check_size(std::size_t size) {
    if ((size >> 20) >= kMallocLimitMiB) {
        allocation_too_large(size);
    }
}

}  // namespace

extern "C" void* malloc(std::size_t size) {
    check_size(size);
    return __libc_malloc(size);
}
extern "C" void* calloc(std::size_t count, std::size_t size) {
    if (size != 0 && count > SIZE_MAX / size) {
        allocation_too_large(SIZE_MAX);
    }
    check_size(count * size);
    return __libc_calloc(count, size);
}
extern "C" void* realloc(void* pointer, std::size_t size) {
    check_size(size);
    return __libc_realloc(pointer, size);
}
#endif

namespace {

// Every regular file under `path` (or `path` itself), skipping dot files (.gitkeep), in name order.
bool collect(const std::filesystem::path& path, std::vector<std::filesystem::path>& files) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) {
        files.push_back(path);
        return true;
    }
    if (!std::filesystem::is_directory(path, ec)) {
        std::fprintf(stderr, "replay: %s: no such file or folder\n", path.c_str());
        return false;
    }
    std::vector<std::filesystem::path> found;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(path)) {
        if (entry.is_regular_file() && entry.path().filename().string().front() != '.') {
            found.push_back(entry.path());
        }
    }
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
    return true;
}

// The input file a harness wrote for a child that crashed before removing it (TemporaryInputFile in
// fuzz_support.hpp: glint-fuzz-<pid>.<extension> in /dev/shm or the temporary folder).
void remove_input_files_of(pid_t child) {
    const std::string prefix = "glint-fuzz-" + std::to_string(child) + ".";
    std::error_code ec;
    for (const std::filesystem::path& folder :
         {std::filesystem::path("/dev/shm"), std::filesystem::temp_directory_path(ec)}) {
        for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
            if (entry.path().filename().string().rfind(prefix, 0) == 0) {
                std::filesystem::remove(entry.path(), ec);
            }
        }
    }
}

// Runs the harness on one input in a child process, so that a crash or a hang stops only that input
// and every input of the folders gets its verdict. Returns whether the input passed.
bool replay(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::fprintf(stderr, "replay: %s (%zu bytes)\n", file.c_str(), bytes.size());
    const auto start = std::chrono::steady_clock::now();
    const pid_t child = ::fork();
    if (child < 0) {
        std::perror("fork");
        return false;
    }
    if (child == 0) {
        ::alarm(kKillSeconds);  // a hang ends here rather than at ctest's timeout
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
        std::exit(0);  // not _exit: static destructors and LeakSanitizer's check run as in the fuzzer
    }
    int status = 0;
    rusage usage{};
    while (::wait4(child, &status, 0, &usage) < 0 && errno == EINTR) {
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    remove_input_files_of(child);
    if (WIFSIGNALED(status)) {
        std::fprintf(stderr, "replay: FAILED %s: %s after %.3f s\n", file.c_str(),
                     strsignal(WTERMSIG(status)), seconds);
        return false;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        std::fprintf(stderr, "replay: FAILED %s: exit code %d after %.3f s\n", file.c_str(),
                     WEXITSTATUS(status), seconds);
        return false;
    }
    if (seconds > kSlowSeconds) {
        std::fprintf(stderr, "replay: FAILED %s: took %.3f s, more than %.0f s\n", file.c_str(), seconds,
                     kSlowSeconds);
        return false;
    }
    const long peak_mb = usage.ru_maxrss / 1024;  // Linux: kilobytes
    if (peak_mb > kRssLimitMb) {
        std::fprintf(stderr, "replay: FAILED %s: used %ld MB, more than %ld MB\n", file.c_str(), peak_mb,
                     kRssLimitMb);
        return false;
    }
    std::fprintf(stderr, "  ok, %.3f s, %ld MB\n", seconds, peak_mb);
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s FOLDER_OR_FILE...\n", argv[0]);
        return 2;
    }
    limit_memory();
    std::vector<std::filesystem::path> files;
    bool all_found = true;
    for (int i = 1; i < argc; ++i) {
        all_found = collect(argv[i], files) && all_found;
    }
    std::vector<std::filesystem::path> failed;
    for (const auto& file : files) {
        if (!replay(file)) {
            failed.push_back(file);
        }
    }
    std::fprintf(stderr, "replay: %zu inputs, %zu failed\n", files.size(), failed.size());
    for (const auto& file : failed) {
        std::fprintf(stderr, "    %s\n", file.c_str());
    }
    return all_found && failed.empty() ? 0 : 1;
}
