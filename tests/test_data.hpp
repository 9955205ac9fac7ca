// Optional test data: the larger meshes and scenes that are not part of the repository (the Stanford
// models of ../shared/data). A clone of glint alone must pass its tests, so a test that reads such a file
// asks for it here and skips, with a message naming the file, when it is not there.
//
// Where the data is: the environment variable GLINT_DATA_DIR when set, otherwise the `shared/data`
// folder beside the repository (GLINT_DEFAULT_DATA_DIR, set by tests/CMakeLists.txt).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

namespace glint::test {

inline std::filesystem::path data_dir() {
    const char* from_environment = std::getenv("GLINT_DATA_DIR");
    return from_environment && *from_environment ? std::filesystem::path(from_environment)
                                                 : std::filesystem::path(GLINT_DEFAULT_DATA_DIR);
}

// The path of `relative` under the data folder, or nullopt when that file is not there.
inline std::optional<std::filesystem::path> optional_data_file(const std::string& relative) {
    const std::filesystem::path path = data_dir() / relative;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        return std::nullopt;
    }
    return path;
}

}  // namespace glint::test

// Binds `variable` to the optional data file `relative`, or skips the test with a message saying what is
// missing and how to provide it.
#define GLINT_REQUIRE_DATA_FILE(variable, relative)                                                         \
    const auto variable##_optional = ::glint::test::optional_data_file(relative);                           \
    if (!variable##_optional) {                                                                             \
        GTEST_SKIP() << "optional test data " << (::glint::test::data_dir() / (relative)).string()          \
                     << " is absent (set GLINT_DATA_DIR to a folder with meshes/ and scenes/ to run this)"; \
    }                                                                                                       \
    const std::filesystem::path& variable = *variable##_optional
