// The HTTP side of `glint serve`: the embedded page, a JSON API to read and edit the scene, and a
// stream of frames as server-sent events. The HTTP library stays inside preview_server.cpp.
//
//   GET  /, /index.html, /app.js, /style.css   the page (embedded; any other path is 404)
//   GET  /api/scene                            the scene tree as JSON, the tables' names, limits
//   POST /api/edit      {"edits": [{"path": [...], "value": ...}]}   → the new scene state, or 4xx
//                       (paths as scene_edit.hpp says: ["materials", "glass", "ior"],
//                       ["objects", 3, "material", "albedo"], ["lights", 0, "intensity"])
//   POST /api/focus     {"x": px, "y": px}      → {"hit", "distance", "depth"}
//   GET  /api/events                           text/event-stream of "frame" events (the frame's data and
//                                              the address of its picture)
//   GET  /api/frames/ID.png                    the latest frame's picture, as binary PNG (whole: a
//                                              delta against the previous frame was measured and does
//                                              not pay with this PNG encoder; see preview_session.cpp)
//   GET  /api/image.png                        the current image, as an attachment
//   GET  /api/scene.yaml                       the scene on screen as YAML, as an attachment
//
// Safe to leave running: every limit is in serve_limits.hpp. Each request is answered (4xx for a bad
// one, 500 if something unforeseen throws), and no client can hold more than its share: connections,
// request size and the time to send a request are bounded before the HTTP library parses anything.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "glint/scene/scene_desc.hpp"
#include "glint/serve/serve_limits.hpp"

namespace glint {

class PreviewSession;

// How much of the server one client may hold. The defaults are preview_limits'; tests shorten them.
struct ConnectionLimits {
    int max_connections = preview_limits::kMaxConnections;
    std::chrono::milliseconds request_deadline = preview_limits::kRequestDeadline;
    std::chrono::milliseconds read_timeout = preview_limits::kReadTimeout;
    std::chrono::milliseconds write_timeout = preview_limits::kWriteTimeout;
    std::chrono::milliseconds idle_timeout = preview_limits::kIdleTimeout;
};

class PreviewServer {
  public:
    // Streams beyond this many get 503: each holds a connection and a thread while open.
    static constexpr int kMaxEventStreams = preview_limits::kMaxEventStreams;

    // Builds the scene (throws SceneError) and starts rendering it.
    PreviewServer(const SceneDesc& desc, const std::string& display_name,
                  const ConnectionLimits& limits = {});
    ~PreviewServer();

    // Binds to host:port (port 0: any free port) and returns the port; throws std::runtime_error.
    int bind(const std::string& host, int port);
    // Serves until stop(); call after bind().
    void run();
    // Ends the event streams, stops accepting and returns from run(); callable from any thread.
    void stop();

    PreviewSession& session();

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace glint
