// What the harnesses of fuzz/ share: the input as a file (for readers that take a path), a tiny render
// of a built scene, and checks that stop the run with a message when a promise of the library is broken.
//
// A harness is one LLVMFuzzerTestOneInput. It is linked twice: with libFuzzer (the fuzz preset, clang)
// to search for crashing inputs, and with replay_main.cpp (every other build) to run the seed corpus
// and the saved regressions as a ctest test.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>

#include "glint/image/film.hpp"
#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_set.hpp"

namespace glint::fuzz {

// A broken promise (an invariant the library documents) is a finding like a crash: abort, so that
// libFuzzer saves the input and the replay test fails, and say which promise.
[[noreturn]] inline void broken_promise(const char* what, const char* file, int line) {
    std::fprintf(stderr, "%s:%d: fuzz check failed: %s\n", file, line, what);
    std::abort();
}
#define GLINT_FUZZ_CHECK(condition) \
    ((condition) ? static_cast<void>(0) : ::glint::fuzz::broken_promise(#condition, __FILE__, __LINE__))

// The input, written to a file with the given extension, for readers that only take a path (the mesh
// loaders, read_image), and removed again when this goes out of scope. The file lives in /dev/shm when
// it exists (no disk traffic for millions of executions) and is named after the process (parallel
// fuzzers do not collide). Removed after every input, not at exit: libFuzzer ends its processes
// without running destructors; only an input that crashes leaves its file behind.
class TemporaryInputFile {
  public:
    TemporaryInputFile(const char* extension, const std::uint8_t* data, std::size_t size)
        : path_(folder() / ("glint-fuzz-" + std::to_string(::getpid()) + extension)) {
        std::FILE* f = std::fopen(path_.c_str(), "wb");
        if (!f) {
            std::perror(path_.c_str());
            std::abort();  // not a finding: the harness cannot work at all
        }
        const bool ok = size == 0 || std::fwrite(data, 1, size, f) == size;
        if (std::fclose(f) != 0 || !ok) {
            std::perror(path_.c_str());
            std::abort();
        }
    }
    ~TemporaryInputFile() {
        std::error_code ec;
        std::filesystem::remove(path_, ec);
    }
    TemporaryInputFile(const TemporaryInputFile&) = delete;
    TemporaryInputFile& operator=(const TemporaryInputFile&) = delete;

    const std::filesystem::path& path() const { return path_; }

  private:
    static const std::filesystem::path& folder() {
        static const std::filesystem::path chosen = [] {
            std::error_code ec;
            const std::filesystem::path shm = "/dev/shm";
            if (std::filesystem::is_directory(shm, ec) && ::access(shm.c_str(), W_OK) == 0) {
                return shm;
            }
            return std::filesystem::temp_directory_path();
        }();
        return chosen;
    }

    std::filesystem::path path_;
};

// The folder relative paths in fuzzed scenes resolve against: fuzz/assets, a few tiny files (a mesh,
// an environment map, a texture) that seeds refer to, so the fuzzer reaches the code that reads them.
inline std::filesystem::path assets_dir() {
    return GLINT_FUZZ_ASSETS_DIR;
}

// What the command line would impose to keep one execution in milliseconds: an 8×8 image, one sample,
// few bounces (and render_tiny runs on one thread). The flags replace the scene's own `render:` values,
// so a harness checks those first with build_view(desc).
inline RenderFlags tiny_render() {
    RenderFlags overrides;
    overrides.width = 8;
    overrides.height = 8;
    overrides.samples_per_pixel = 1;
    overrides.max_depth = 3;
    return overrides;
}

// Renders a scene built with tiny_render(). Rendering a checked scene must not fail: any exception
// escapes to the harness's caller and is a finding.
inline void render_tiny(Scene& scene) {
    scene.view.settings.threads = 1;
    Film film(scene.view.settings.width, scene.view.settings.height);
    const RenderStats stats = render(scene, film);
    GLINT_FUZZ_CHECK(!stats.cancelled);
}

// An input the library refused, as documented. With GLINT_FUZZ_VERBOSE set the reason is printed: how
// to see which seeds are refused, and why (a seed that never gets past the parser finds little).
inline void refused(const std::exception& e) {
    static const bool verbose = std::getenv("GLINT_FUZZ_VERBOSE") != nullptr;
    if (verbose) {
        std::fprintf(stderr, "  refused: %s\n", e.what());
    }
}

// A SceneError's report starts with a position or a path and says "error:" (docs/scene-format.md).
inline void check_scene_error(const std::exception& e) {
    refused(e);
    const std::string_view what = e.what();
    GLINT_FUZZ_CHECK(what.find("error: ") != std::string_view::npos);
}

}  // namespace glint::fuzz
