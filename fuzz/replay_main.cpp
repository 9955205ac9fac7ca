// The main() of a harness outside libFuzzer: runs LLVMFuzzerTestOneInput once on every file of the
// folders (and files) given, in name order. ctest runs each harness this way over its seed corpus and
// its saved regressions (fuzz/CMakeLists.txt), so every build — g++ release, the sanitize preset —
// replays what the fuzzer once found, without clang or libFuzzer.
//
// A finding shows as a crash (the input's path was printed just before), an abort from a failed check,
// a single allocation of 2 GiB or more (as libFuzzer's -malloc_limit_mb, see below), or an input slower
// than kSlowSeconds (a replayed input must stay far from the fuzzer's -timeout).
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
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

constexpr double kSlowSeconds = 10;  // libFuzzer's -timeout in fuzz/run.sh

#if defined(GLINT_REPLAY_UNDER_ASAN)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
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
// malloc: under the sanitize preset, ctest sets ASAN_OPTIONS=max_allocation_size_mb=2048 instead.
#if !defined(GLINT_REPLAY_UNDER_ASAN)
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
    int slow = 0;
    for (const auto& file : files) {
        std::ifstream in(file, std::ios::binary);
        const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::fprintf(stderr, "replay: %s (%zu bytes)\n", file.c_str(), bytes.size());
        const auto start = std::chrono::steady_clock::now();
        LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (seconds > kSlowSeconds) {
            std::fprintf(stderr, "replay: %s took %.1f s (more than %.0f s): a finding\n", file.c_str(),
                         seconds, kSlowSeconds);
            ++slow;
        }
    }
    std::fprintf(stderr, "replay: %zu inputs, %d too slow\n", files.size(), slow);
    return all_found && slow == 0 ? 0 : 1;
}
