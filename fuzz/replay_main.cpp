// The main() of a harness outside libFuzzer: runs LLVMFuzzerTestOneInput once on every file of the
// folders (and files) given, in name order. ctest runs each harness this way over its seed corpus and
// its saved regressions (fuzz/CMakeLists.txt), so every build — g++ release, the sanitize preset —
// replays what the fuzzer once found, without clang or libFuzzer.
//
// A finding shows as a crash (the input's path was printed just before), an abort from a failed check,
// or an input slower than kSlowSeconds (a replayed input must stay far from the fuzzer's -timeout).
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

constexpr double kSlowSeconds = 10;  // libFuzzer's -timeout in fuzz/run.sh

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// As the fuzzer's -rss_limit_mb=2048 would, stop an input that wants unbounded memory before it
// takes the machine's: without AddressSanitizer (which reserves terabytes of address space), cap the
// address space, so a huge allocation fails with bad_alloc, an uncaught exception, a finding.
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
