// Which files a folder had opened: the preview's tests check what an edit reads (and what it must not).
#pragma once

#include <gtest/gtest.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace glint::test {

// The names of the files opened in a folder since the last call.
class OpenWatch {
  public:
    explicit OpenWatch(const std::filesystem::path& dir, std::uint32_t mask = IN_OPEN)
        : fd_(::inotify_init1(IN_NONBLOCK)) {
        EXPECT_GE(fd_, 0);
        EXPECT_GE(::inotify_add_watch(fd_, dir.c_str(), mask), 0);
    }
    ~OpenWatch() { ::close(fd_); }
    std::vector<std::string> opened() {
        std::vector<std::string> names;
        alignas(inotify_event) char buffer[8192];
        for (ssize_t n; (n = ::read(fd_, buffer, sizeof(buffer))) > 0;) {
            for (ssize_t at = 0; at < n;) {
                const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
                names.emplace_back(event->len ? event->name : "");
                at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
            }
        }
        return names;
    }

  private:
    int fd_;
};

}  // namespace glint::test
