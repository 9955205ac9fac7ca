// The HTTP side of `glint serve`: the embedded page, a JSON API to read and edit the scene, and a
// stream of frames as server-sent events. The HTTP library stays inside preview_server.cpp.
//
//   GET  /, /index.html, /app.js, /style.css   the page (embedded; any other path is 404)
//   GET  /api/scene                            the scene tree as JSON, the tables' names, limits
//   POST /api/edit      {"edits": [{"path": [...], "value": ...}]}   → the new scene state, or 400
//   POST /api/focus     {"x": px, "y": px}      → {"hit", "distance", "depth"}
//   GET  /api/events                           text/event-stream of "frame" events (PNG as base64)
//   GET  /api/image.png                        the current image, as an attachment
//   GET  /api/scene.yaml                       the scene on screen as YAML, as an attachment
#pragma once

#include <memory>
#include <string>

#include "glint/scene/scene_desc.hpp"

namespace glint {

class PreviewSession;

class PreviewServer {
  public:
    // Streams beyond this many get 503: each holds one thread of the pool while open.
    static constexpr int kMaxEventStreams = 32;
    // Threads answering requests: every event stream plus as many for ordinary requests.
    static constexpr int kThreads = 2 * kMaxEventStreams;

    // Builds the scene (throws SceneError) and starts rendering it.
    PreviewServer(const SceneDesc& desc, const std::string& display_name);
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
