// Ctrl-C and SIGTERM during `glint render`: the first Ctrl-C writes the image reached so far, a second
// one (or SIGTERM) quits at once, and neither leaves a half-written file behind.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "glint/image/image_io.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

// A render that takes many seconds: the default scene path-traced at 4096 samples per pixel.
const std::string kLongRender = "render --width 96 --height 54 --spp 4096 --sampler random --integrator path";

struct Running {
    pid_t pid = -1;
    std::filesystem::path log;
};

// Starts glint with `arguments` (split on spaces), stderr to a log file.
Running start_glint(const std::string& arguments, const test::TempDir& dir) {
    std::vector<std::string> words{GLINT_CLI_PATH};
    std::istringstream in(arguments);
    for (std::string w; in >> w;) {
        words.push_back(w);
    }
    Running run;
    run.log = dir / "log.txt";
    run.pid = ::fork();
    if (run.pid == 0) {
        std::freopen(run.log.c_str(), "w", stderr);
        std::vector<char*> argv;
        for (auto& w : words) {
            argv.push_back(w.data());
        }
        argv.push_back(nullptr);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    return run;
}

std::string read_text(const std::filesystem::path& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Waits for the process to end (at most a minute); its exit code, or -1 if it had to be killed. A death
// by a signal is 1000 + the signal: glint must exit, not be killed, even when it is told to stop.
int wait_exit(pid_t pid) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
    while (std::chrono::steady_clock::now() < deadline) {
        int status = 0;
        if (::waitpid(pid, &status, WNOHANG) == pid) {
            return WIFEXITED(status) ? WEXITSTATUS(status) : 1000 + WTERMSIG(status);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ::kill(pid, SIGKILL);
    ::waitpid(pid, nullptr, 0);
    return -1;
}

// Waits until glint has installed its SIGINT and SIGTERM handlers (the SigCgt mask in /proc), then a
// little longer, for the small default scene to be built and the render to begin.
void let_it_start(pid_t pid) {
    const std::uint64_t wanted = (1u << (SIGINT - 1)) | (1u << (SIGTERM - 1));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (std::chrono::steady_clock::now() < deadline) {
        std::ifstream status("/proc/" + std::to_string(pid) + "/status");
        std::uint64_t caught = 0;
        for (std::string line; std::getline(status, line);) {
            if (line.rfind("SigCgt:", 0) == 0) {
                caught = std::stoull(line.substr(7), nullptr, 16);
            }
        }
        if ((caught & wanted) == wanted) {
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
}

// Files in `dir` other than the log: the image, or a temporary file left behind.
std::vector<std::string> files_besides_log(const test::TempDir& dir) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
        if (entry.path().filename() != "log.txt") {
            names.push_back(entry.path().filename().string());
        }
    }
    return names;
}

TEST(Interrupt, FirstCtrlCWritesTheSamplesTakenSoFar) {
    test::TempDir dir;
    const auto out = dir / "partial.pfm";
    const Running run = start_glint(kLongRender + " -o " + out.string(), dir);
    let_it_start(run.pid);
    ASSERT_EQ(::kill(run.pid, SIGINT), 0);
    EXPECT_EQ(wait_exit(run.pid), 130);
    const std::string log = read_text(run.log);
    ASSERT_TRUE(std::filesystem::exists(out)) << log;
    EXPECT_EQ(files_besides_log(dir).size(), 1u) << "a temporary file was left behind";
    // "interrupted: wrote … with N of 4096 samples per pixel"
    const auto at = log.find("interrupted: wrote");
    ASSERT_NE(at, std::string::npos) << log;
    const auto with = log.find(" with ", at);
    const unsigned reached = static_cast<unsigned>(std::stoul(log.substr(with + 6)));
    EXPECT_GT(reached, 0u);
    EXPECT_LT(reached, 4096u);
    // Every pixel is the mean of the samples it really has: the same bits as a render asked for exactly
    // that many samples (the random pattern's sample i does not depend on the total).
    const auto full = dir / "full.pfm";
    const auto r = test::run_glint("render --width 96 --height 54 --spp " + std::to_string(reached) +
                                   " --sampler random --integrator path --quiet -o " + full.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(read_pfm(out).rgb, read_pfm(full).rgb);
}

TEST(Interrupt, SecondCtrlCQuitsAtOnceWithoutAFile) {
    test::TempDir dir;
    // Slow passes (a large image, long paths), so that the second Ctrl-C comes while one runs.
    const Running run =
        start_glint("render --width 1280 --height 720 --spp 4096 --integrator path --max-depth 64 -o " +
                        (dir / "never.png").string(),
                    dir);
    let_it_start(run.pid);
    ::kill(run.pid, SIGINT);
    // The second only once the first was handled (two pending SIGINTs would merge into one): its
    // message is in the log. A pass of this image takes seconds, so the render is still in it.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (read_text(run.log).find("stopping after this pass") == std::string::npos &&
           std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ::kill(run.pid, SIGINT);
    EXPECT_EQ(wait_exit(run.pid), 130);
    EXPECT_TRUE(files_besides_log(dir).empty()) << read_text(run.log);
}

TEST(Interrupt, SigtermQuitsWithoutAFile) {
    test::TempDir dir;
    const Running run = start_glint(kLongRender + " -o " + (dir / "never.exr").string(), dir);
    let_it_start(run.pid);
    ::kill(run.pid, SIGTERM);
    EXPECT_EQ(wait_exit(run.pid), 143);
    EXPECT_TRUE(files_besides_log(dir).empty()) << read_text(run.log);
}

}  // namespace
}  // namespace glint
