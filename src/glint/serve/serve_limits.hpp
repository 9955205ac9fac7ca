// Every limit of `glint serve`, in one place: what a scene on screen may cost, what an edit request
// may hold, and what one client may take of the server. Each says why it is what it is; the README's
// "glint serve" section lists them for users. The preview is meant to be left running with a browser
// (or anything else that can reach the port) talking to it, so nothing a request says may make it
// allocate, compute or wait without a bound.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace glint::preview_limits {

// --- The scene on screen (the loaded scene and every edit of it) ------------------------------------

// Image side: the page shows the image in a browser window; larger pictures are for `glint render`.
inline constexpr std::int64_t kMaxSide = 4096;
// Pixels: the preview keeps a film (40 bytes a pixel), an image (12) and the frame's linear copy for
// Save EXR (12) and a PNG in each frame, twice over while an edit replaces the scene: about 125 bytes a
// pixel at most, so ~520 MB here.
inline constexpr std::int64_t kMaxPixels = 2048 * 2048;
// Samples per pixel: the preview refines until it has them, with every core busy; past this the wait
// is hours, which is a job for `glint render`.
inline constexpr std::int64_t kMaxSamples = 16384;
// Bounces: the cost of Whitted's tree (two rays at each dielectric) and of paths grows with it, and the
// page's slider stops here.
inline constexpr std::int64_t kMaxDepth = 64;

// The numeric keys that set the cost of a frame. (Other keys the page may edit have ranges the scene
// builder checks and costs that do not grow with their value, or grow within the builder's bound:
// noise octaves are at most 16, a light's shadow rays at most 4096, the tree is at most kMaxPathLength
// deep; objects and lights, whose number sets the cost too, are edited in place, never added.)
struct NumericLimit {
    std::string_view section, key;
    std::int64_t maximum;
};
inline constexpr std::array<NumericLimit, 5> kNumericLimits = {{
    {"render", "width", kMaxSide},
    {"render", "height", kMaxSide},
    {"render", "samples", kMaxSamples},
    {"render", "max_depth", kMaxDepth},
    {"render.integrator", "max_depth", kMaxDepth},  // an integrator's own, which wins over render's
}};

// --- One edit request ---------------------------------------------------------------------------------

// The body of a POST: an edit of every key the page shows is a few kilobytes.
inline constexpr std::size_t kMaxRequestBodyBytes = 64 * 1024;
// JSON nesting: {"edits": [{"path": [...], "value": [...]}]} is 4 deep; deeper is refused while parsing,
// before anything recursive (copy, dump, destruction) walks it.
inline constexpr int kMaxJsonDepth = 8;
inline constexpr std::size_t kMaxEdits = 64;       // edits in one request
inline constexpr std::size_t kMaxPathLength = 8;   // keys in one path, so the tree stays shallow
inline constexpr std::size_t kMaxListLength = 16;  // numbers in one list value (colours, points: 3)
inline constexpr std::size_t kMaxWordLength = 64;  // characters in one key or word value

// --- Connections ----------------------------------------------------------------------------------------

// Open connections at once, event streams included; the next is answered 503 at once and closed.
inline constexpr int kMaxConnections = 64;
// Event streams at once (each holds a connection for as long as a tab is open); more get 503.
inline constexpr int kMaxEventStreams = 32;
// Threads answering: one per connection, and a few more so that refusing is never queued behind them.
inline constexpr int kThreads = kMaxConnections + 8;
// The request line and headers together, in bytes: what a browser sends is 1–2 KB, even with cookies
// for localhost it stays well below. Bounds the memory a request takes before any handler runs.
inline constexpr std::size_t kMaxHeadBytes = 16 * 1024;
// Header lines in one request (browsers send about 15).
inline constexpr int kMaxHeaderCount = 64;
// Body bytes on the wire: the body limit plus room for chunked framing.
inline constexpr std::size_t kMaxBodyWireBytes = kMaxRequestBodyBytes + 16 * 1024;
// A whole request (line, headers and body) must arrive within this, counted from its first byte, so
// that a client trickling bytes cannot hold a connection.
inline constexpr std::chrono::milliseconds kRequestDeadline{10'000};
// Longest wait for the next bytes of a request, and for a write to make progress.
inline constexpr std::chrono::milliseconds kReadTimeout{5'000};
inline constexpr std::chrono::milliseconds kWriteTimeout{5'000};
// An idle connection (before its first request, or between requests) is closed after this.
inline constexpr std::chrono::milliseconds kIdleTimeout{2'000};
// Requests on one connection before it is closed (the client reconnects).
inline constexpr int kMaxRequestsPerConnection = 100;
// The longest URL path served: the page's files and the API have short names.
inline constexpr std::size_t kMaxPathBytes = 256;

}  // namespace glint::preview_limits
