#include "glint/serve/preview_server.hpp"

// The packaged cpp-httplib (Debian's 0.11) is a compiled library: its CPPHTTPLIB_* limits are fixed in
// it (request line 8192 bytes, each header line 8192 bytes, no bound on the number of headers, on a
// body sent without Content-Length or chunked, or on the time a request may take), and defining them
// here would change nothing. So the server below reads every byte through its own stream, which
// bounds all of that before httplib parses anything; httplib keeps the parsing and the routing.
#include <arpa/inet.h>
#include <httplib.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <nlohmann/json.hpp>

#include "glint/camera/camera.hpp"
#include "glint/image/image_io.hpp"
#include "glint/image/tone_map.hpp"
#include "glint/integrator/integrator.hpp"
#include "glint/light/light.hpp"
#include "glint/material/material.hpp"
#include "glint/sampling/sampler.hpp"
#include "glint/serve/preview_session.hpp"
#include "glint/serve/web_assets.hpp"

namespace glint {

namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// An idle stream writes a comment this often, which is also how a closed browser tab is noticed.
constexpr auto kKeepAliveComment = std::chrono::seconds(2);
// Large answers (frames, the PNG) are written this much at a time.
constexpr size_t kWriteSlice = 64 * 1024;
// Waits are cut into slices this long, so that stop() is noticed promptly.
constexpr milliseconds kWaitSlice{100};
// After refusing a request, the rest of what the client sent is read (and dropped) for at most this
// long and this many bytes before the socket is closed: closing with unread bytes would reset the
// connection, and the client could lose the answer that says why.
constexpr milliseconds kLingerTime{200};
constexpr std::size_t kLingerBytes = 256 * 1024;

// Set by a handler (on the connection's own thread) to close the connection after its answer: a
// request refused before its body was read leaves that body on the wire.
thread_local bool t_close_connection = false;

std::string dump_json(const nlohmann::ordered_json& body) {
    // Replace, not throw on, invalid UTF-8: a file name or an echoed value must not turn an answer
    // into an exception.
    return body.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

const char* reason_phrase(int status) {
    switch (status) {
        case 408:
            return "Request Timeout";
        case 413:
            return "Payload Too Large";
        case 431:
            return "Request Header Fields Too Large";
        case 503:
            return "Service Unavailable";
        default:
            return "Bad Request";
    }
}

// A whole response written directly to the socket, for refusals made below httplib (no request was
// parsed, so httplib cannot answer them).
std::string canned_response(int status, const std::string& message) {
    const std::string body = dump_json({{"error", message}});
    return "HTTP/1.1 " + std::to_string(status) + " " + reason_phrase(status) +
           "\r\nContent-Type: application/json\r\nCache-Control: no-store\r\nContent-Length: " +
           std::to_string(body.size()) + "\r\nConnection: close\r\n\r\n" + body;
}

// Best effort: sends what the socket takes within its send timeout.
void send_all(int sock, const std::string& bytes) {
    size_t sent = 0;
    while (sent < bytes.size()) {
        const ssize_t n = ::send(sock, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) {
            continue;
        }
        if (n <= 0) {
            return;
        }
        sent += static_cast<size_t>(n);
    }
}

// Ends our side and reads what the client still sends, within kLingerTime and kLingerBytes.
void linger_close(int sock) {
    ::shutdown(sock, SHUT_WR);
    const auto until = Clock::now() + kLingerTime;
    std::size_t drained = 0;
    char scratch[4096];
    while (drained < kLingerBytes) {
        const auto left = std::chrono::duration_cast<milliseconds>(until - Clock::now()).count();
        if (left <= 0) {
            return;
        }
        pollfd fd{sock, POLLIN, 0};
        const int ready = ::poll(&fd, 1, static_cast<int>(left));
        if (ready < 0 && errno == EINTR) {
            continue;
        }
        if (ready <= 0) {
            return;
        }
        const ssize_t n = ::recv(sock, scratch, sizeof(scratch), MSG_DONTWAIT);
        if (n <= 0 && !(n < 0 && (errno == EINTR || errno == EAGAIN))) {
            return;  // the client closed too, or the connection failed
        }
        drained += n > 0 ? static_cast<size_t>(n) : 0;
    }
}

std::string seconds_text(milliseconds duration) {
    char text[32];
    std::snprintf(text, sizeof(text), "%g s", static_cast<double>(duration.count()) / 1000.0);
    return text;
}

void address_of(int sock, bool peer, std::string& ip, int& port) {
    sockaddr_storage address{};
    socklen_t length = sizeof(address);
    auto* any = reinterpret_cast<sockaddr*>(&address);
    if ((peer ? ::getpeername(sock, any, &length) : ::getsockname(sock, any, &length)) != 0) {
        return;
    }
    char text[INET6_ADDRSTRLEN] = {};
    if (address.ss_family == AF_INET) {
        const auto* v4 = reinterpret_cast<const sockaddr_in*>(&address);
        ::inet_ntop(AF_INET, &v4->sin_addr, text, sizeof(text));
        port = ntohs(v4->sin_port);
    } else if (address.ss_family == AF_INET6) {
        const auto* v6 = reinterpret_cast<const sockaddr_in6*>(&address);
        ::inet_ntop(AF_INET6, &v6->sin6_addr, text, sizeof(text));
        port = ntohs(v6->sin6_port);
    }
    ip = text;
}

// A client connection as httplib reads and writes it, with the bounds httplib lacks. Each request
// (begin_request) gets kMaxHeadBytes for its request line and headers, at most kMaxHeaderCount header
// lines, kMaxBodyWireBytes for its body, and must arrive whole before its deadline; past any of these
// the stream answers 431, 413 or 408 itself, then fails every read and write, so httplib gives up
// on the request and the connection is closed. Memory per connection is therefore bounded before
// httplib stores a single header.
//
// httplib reads the request line and headers one byte at a time (its line reader), so the stream
// sees exactly where the head ends: at the first empty line after the request line.
class BoundedSocketStream final : public httplib::Stream {
  public:
    BoundedSocketStream(int sock, const ConnectionLimits& limits, std::function<bool()> stopping)
        : sock_(sock), limits_(limits), stopping_(std::move(stopping)) {}

    void begin_request() {
        deadline_ = Clock::now() + limits_.request_deadline;
        in_head_ = true;
        head_bytes_ = 0;
        body_bytes_ = 0;
        lines_ = 0;
        line_bytes_ = 0;
        previous_ = 0;
        wrote_ = false;
    }
    bool has_buffered() const { return buffer_begin_ < buffer_end_; }
    bool refused() const { return refused_; }

    bool is_readable() const override {
        if (has_buffered()) {
            return true;
        }
        pollfd fd{sock_, POLLIN, 0};
        return ::poll(&fd, 1, static_cast<int>(limits_.read_timeout.count())) > 0;
    }

    bool is_writable() const override { return !refused_ && wait_writable() && peer_open(); }

    ssize_t read(char* out, size_t size) override {
        if (refused_) {
            return -1;
        }
        if (!has_buffered()) {
            const ssize_t filled = fill();
            if (filled <= 0) {
                return filled;
            }
        }
        size_t n = 0;
        while (n < size && has_buffered()) {
            if (in_head_) {
                if (head_bytes_ >= preview_limits::kMaxHeadBytes) {
                    refuse(431, "the request line and headers may take at most " +
                                    std::to_string(preview_limits::kMaxHeadBytes) + " bytes");
                    return -1;
                }
                const char c = buffer_[buffer_begin_++];
                out[n++] = c;
                ++head_bytes_;
                ++line_bytes_;
                if (c == '\n') {
                    if (lines_ > 0 && line_bytes_ == 2 && previous_ == '\r') {
                        in_head_ = false;  // the empty line: the body (if any) follows
                    } else if (++lines_ > preview_limits::kMaxHeaderCount + 1) {
                        refuse(431, "a request may have at most " +
                                        std::to_string(preview_limits::kMaxHeaderCount) + " header lines");
                        return -1;
                    }
                    line_bytes_ = 0;
                }
                previous_ = c;
                if (!in_head_) {
                    break;  // what follows counts against the body's budget
                }
            } else {
                const size_t chunk = std::min(size - n, buffer_end_ - buffer_begin_);
                if (body_bytes_ + chunk > preview_limits::kMaxBodyWireBytes) {
                    refuse(413, "a request body may have at most " +
                                    std::to_string(preview_limits::kMaxRequestBodyBytes) + " bytes");
                    return -1;
                }
                std::memcpy(out + n, buffer_.data() + buffer_begin_, chunk);
                buffer_begin_ += chunk;
                body_bytes_ += chunk;
                n += chunk;
            }
        }
        return static_cast<ssize_t>(n);
    }

    ssize_t write(const char* data, size_t size) override {
        // No peer_open() here: a client that half-closes after its request (`nc -N`) still reads the
        // answer; a socket closed for good fails the send (EPIPE). is_writable() keeps the check, for
        // the event streams' loop, which must notice a page that went away without writing to it.
        if (refused_ || !wait_writable()) {
            return -1;
        }
        wrote_ = true;
        ssize_t n;
        do {
            n = ::send(sock_, data, size, MSG_NOSIGNAL);
        } while (n < 0 && errno == EINTR);
        return n;
    }

    void get_remote_ip_and_port(std::string& ip, int& port) const override {
        address_of(sock_, true, ip, port);
    }
    void get_local_ip_and_port(std::string& ip, int& port) const override {
        address_of(sock_, false, ip, port);
    }
    socket_t socket() const override { return sock_; }

  private:
    // Reads what the socket has into the buffer: > 0 bytes, 0 at the end of the stream, -1 on a
    // timeout, stop or error. A request that has begun and runs out of time is answered 408.
    ssize_t fill() {
        const auto read_until = std::min(Clock::now() + limits_.read_timeout, deadline_);
        while (true) {
            if (stopping_()) {
                return -1;
            }
            const auto now = Clock::now();
            if (now >= read_until) {
                refuse(408, "the request did not arrive in time (a request must arrive whole within " +
                                seconds_text(limits_.request_deadline) + ", with no pause longer than " +
                                seconds_text(limits_.read_timeout) + ")");
                return -1;
            }
            const auto slice = std::min<milliseconds>(
                kWaitSlice, std::chrono::duration_cast<milliseconds>(read_until - now) + milliseconds(1));
            pollfd fd{sock_, POLLIN, 0};
            const int ready = ::poll(&fd, 1, static_cast<int>(slice.count()));
            if (ready < 0 && errno != EINTR) {
                return -1;
            }
            if (ready <= 0) {
                continue;
            }
            const ssize_t n = ::recv(sock_, buffer_.data(), buffer_.size(), MSG_DONTWAIT);
            if (n < 0 && (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK)) {
                continue;
            }
            if (n <= 0) {
                return n;
            }
            buffer_begin_ = 0;
            buffer_end_ = static_cast<size_t>(n);
            return n;
        }
    }

    bool wait_writable() const {
        const auto until = Clock::now() + limits_.write_timeout;
        while (!stopping_()) {
            const auto now = Clock::now();
            if (now >= until) {
                return false;
            }
            const auto slice = std::min<milliseconds>(
                kWaitSlice, std::chrono::duration_cast<milliseconds>(until - now) + milliseconds(1));
            pollfd fd{sock_, POLLOUT, 0};
            const int ready = ::poll(&fd, 1, static_cast<int>(slice.count()));
            if (ready > 0) {
                return (fd.revents & (POLLERR | POLLHUP)) == 0;
            }
            if (ready < 0 && errno != EINTR) {
                return false;
            }
        }
        return false;
    }

    // False once the client has closed its side: an event stream to a closed tab then ends at its
    // next write instead of filling the socket's buffer.
    bool peer_open() const {
        pollfd fd{sock_, POLLIN, 0};
        if (::poll(&fd, 1, 0) <= 0) {
            return true;
        }
        char byte;
        return ::recv(sock_, &byte, 1, MSG_PEEK | MSG_DONTWAIT) > 0;
    }

    void refuse(int status, const std::string& message) {
        if (!wrote_) {
            send_all(sock_, canned_response(status, message));
        }
        refused_ = true;
    }

    int sock_;
    ConnectionLimits limits_;
    std::function<bool()> stopping_;
    std::array<char, 4096> buffer_{};
    size_t buffer_begin_ = 0, buffer_end_ = 0;

    Clock::time_point deadline_ = Clock::now();
    bool in_head_ = true;
    size_t head_bytes_ = 0, body_bytes_ = 0, line_bytes_ = 0;
    int lines_ = 0;
    char previous_ = 0;
    bool wrote_ = false;
    bool refused_ = false;
};

// httplib's server with its connection handling replaced (the one virtual it offers for that): a cap
// on open connections, an idle timeout between requests, and BoundedSocketStream for each. Requests
// are parsed, routed and answered by httplib's own process_request.
class GuardedHttpServer final : public httplib::Server {
  public:
    explicit GuardedHttpServer(const ConnectionLimits& limits) : limits_(limits) {}

  private:
    bool process_and_close_socket(socket_t sock) override {
        bool ok = false;
        try {
            ok = serve_connection(sock);
        } catch (...) {
            ok = false;  // nothing may leave this function: in the thread pool it would end the process
        }
        ::shutdown(sock, SHUT_RDWR);
        ::close(sock);
        return ok;
    }

    bool stopping() const { return svr_sock_ == INVALID_SOCKET; }

    bool serve_connection(int sock) {
        const int already_open = open_connections_.fetch_add(1);
        struct Slot {
            std::atomic<int>& open;
            ~Slot() { open.fetch_sub(1); }
        } slot{open_connections_};
        t_close_connection = false;
        if (already_open >= limits_.max_connections) {
            send_all(sock, canned_response(503, "too many open connections (at most " +
                                                    std::to_string(limits_.max_connections) +
                                                    "); try again in a moment"));
            linger_close(sock);
            return false;
        }
        BoundedSocketStream stream(sock, limits_, [this] { return stopping(); });
        bool ok = false;
        for (int served = 0; served < preview_limits::kMaxRequestsPerConnection; ++served) {
            if (!wait_for_request(sock, stream)) {
                break;
            }
            stream.begin_request();
            t_close_connection = false;
            bool connection_closed = false;
            const bool last = served + 1 == preview_limits::kMaxRequestsPerConnection;
            ok = process_request(stream, last, connection_closed, nullptr);
            if (!ok || connection_closed || stream.refused() || t_close_connection) {
                break;
            }
        }
        if (stream.refused() || t_close_connection) {
            linger_close(sock);  // what the client still sends is read, so that it gets the answer
        }
        return ok;
    }

    // Waits for the first byte of the next request, at most the idle timeout.
    bool wait_for_request(int sock, const BoundedSocketStream& stream) const {
        if (stream.has_buffered()) {
            return true;
        }
        const auto until = Clock::now() + limits_.idle_timeout;
        while (!stopping()) {
            const auto now = Clock::now();
            if (now >= until) {
                return false;
            }
            const auto slice = std::min<milliseconds>(
                kWaitSlice, std::chrono::duration_cast<milliseconds>(until - now) + milliseconds(1));
            pollfd fd{sock, POLLIN, 0};
            const int ready = ::poll(&fd, 1, static_cast<int>(slice.count()));
            if (ready > 0) {
                return true;  // data, or the end of the stream (which the first read then sees)
            }
            if (ready < 0 && errno != EINTR) {
                return false;
            }
        }
        return false;
    }

    ConnectionLimits limits_;
    std::atomic<int> open_connections_{0};
};

void send_json(httplib::Response& res, const nlohmann::ordered_json& body, int status = 200) {
    res.status = status;
    res.set_header("Cache-Control", "no-store");
    res.set_content(dump_json(body), "application/json");
}

void send_error(httplib::Response& res, int status, const std::string& message) {
    send_json(res, {{"error", message}}, status);
}

// Whether the request says it is JSON; answers 415 when not.
bool json_content_type(const httplib::Request& req, httplib::Response& res) {
    const std::string type = req.get_header_value("Content-Type");
    if (type.rfind("application/json", 0) != 0) {
        // Also what keeps other web sites out: a cross-origin JSON POST needs a preflight we refuse.
        send_error(res, 415, "send the request as Content-Type: application/json");
        return false;
    }
    return true;
}

// A handler that answers every failure: no exception leaves it, whatever throws inside.
httplib::Server::Handler guarded(std::function<void(const httplib::Request&, httplib::Response&)> handler) {
    return [handler = std::move(handler)](const httplib::Request& req, httplib::Response& res) {
        try {
            handler(req, res);
        } catch (const RequestTooLargeError& e) {
            send_error(res, 413, e.what());
        } catch (const PreviewLimitError& e) {
            send_json(res, {{"error", e.what()}, {"key", e.key}, {"value", e.value}, {"maximum", e.maximum}},
                      422);
        } catch (const FileReferenceError& e) {
            send_error(res, 403, e.what());
        } catch (const EditError& e) {
            send_error(res, 400, e.what());
        } catch (const SceneError& e) {
            send_error(res, 422, e.what());
        } catch (const std::exception& e) {
            send_error(res, 500, std::string("internal error: ") + e.what());
        } catch (...) {
            send_error(res, 500, "internal error");
        }
    };
}

template <typename Table>
nlohmann::ordered_json names_of(const Table& table) {
    auto list = nlohmann::ordered_json::array();
    for (const auto& entry : table) {
        list.push_back(entry.name);
    }
    return list;
}

template <typename Table>
nlohmann::ordered_json described(const Table& table) {
    auto list = nlohmann::ordered_json::array();
    for (const auto& entry : table) {
        list.push_back({{"name", entry.name}, {"summary", entry.summary}});
    }
    return list;
}

}  // namespace

struct PreviewServer::Impl {
    PreviewSession session;
    GuardedHttpServer http;
    std::string host;
    int port = 0;
    std::atomic<int> open_streams{0};
    std::atomic<bool> stopping{false};
    int listen_socket = -1;

    Impl(const SceneDesc& desc, const std::string& name, const ConnectionLimits& limits)
        : session(desc, name), http(limits) {}

    nlohmann::ordered_json state_json() const {
        const PreviewSession::State state = session.state();
        const PreviewStatus status = session.status();
        return {{"name", session.display_name()},
                {"generation", state.generation},
                {"width", state.settings.width},
                {"height", state.settings.height},
                {"settings",
                 {{"samples", state.settings.samples_per_pixel},
                  {"sampler", state.settings.sampler},
                  {"integrator", state.settings.integrator},
                  {"max_depth", state.settings.max_depth},
                  {"seed", state.settings.seed}}},
                {"continuous", session.continuous()},
                {"extendable", state.extendable},
                {"scene", node_to_json(state.root)},
                {"yaml", state.yaml},
                {"render_error", status.generation == state.generation ? status.error : ""},
                {"samplers", described(sampler_table())},
                {"integrators", described(integrator_table())},
                {"cameras", names_of(camera_table())},
                {"material_types", names_of(material_table())},
                {"light_types", names_of(light_table())},
                {"max_pixels", preview_limits::kMaxPixels},
                {"limits",
                 {{"width", preview_limits::kMaxSide},
                  {"height", preview_limits::kMaxSide},
                  {"pixels", preview_limits::kMaxPixels},
                  {"samples", preview_limits::kMaxSamples},
                  {"max_depth", preview_limits::kMaxDepth}}}};
    }

    // A loopback server answers only to its own names, so that a web page that rebinds its DNS name to
    // 127.0.0.1 cannot read the scene or drive the server.
    bool host_allowed(const httplib::Request& req) const {
        if (host != "127.0.0.1" && host != "localhost" && host != "::1") {
            return true;
        }
        const std::string value = req.get_header_value("Host");
        const std::string port_text = std::to_string(port);
        for (const std::string_view name : {"127.0.0.1", "localhost", "[::1]"}) {
            const std::string_view v = value;
            if (v == name ||
                (v.size() == name.size() + 1 + port_text.size() && v.substr(0, name.size()) == name &&
                 v[name.size()] == ':' && v.substr(name.size() + 1) == port_text)) {
                return true;
            }
        }
        return false;
    }

    void routes() {
        http.new_task_queue = [] { return new httplib::ThreadPool(preview_limits::kThreads); };
        // Keep httplib's own socket options (address reuse) and remember the socket, see bind().
        http.set_socket_options([this](int socket) {
            int yes = 1;
            ::setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
            listen_socket = socket;
        });
        // What httplib itself still checks. (The timeouts set the accepted sockets' SO_RCVTIMEO and
        // SO_SNDTIMEO; the waits themselves are GuardedHttpServer's.)
        http.set_payload_max_length(preview_limits::kMaxRequestBodyBytes);
        // Only for the Keep-Alive header httplib writes, so that it tells clients what the server does.
        http.set_keep_alive_timeout(
            std::chrono::duration_cast<std::chrono::seconds>(preview_limits::kIdleTimeout).count());
        http.set_keep_alive_max_count(preview_limits::kMaxRequestsPerConnection);
        http.set_read_timeout(
            std::chrono::duration_cast<std::chrono::seconds>(preview_limits::kReadTimeout).count());
        http.set_write_timeout(
            std::chrono::duration_cast<std::chrono::seconds>(preview_limits::kWriteTimeout).count());

        http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
            res.set_header("X-Content-Type-Options", "nosniff");
            const auto refuse = [&](int status, const std::string& message) {
                t_close_connection = true;  // the body, if any, is left unread on the wire
                send_error(res, status, message);
                return httplib::Server::HandlerResponse::Handled;
            };
            if (!host_allowed(req)) {
                return refuse(403, "glint serve answers to 127.0.0.1 and localhost only");
            }
            // Before the routes' regular expressions see the path (their matching recurses per
            // character): every path served is short.
            if (req.path.size() > preview_limits::kMaxPathBytes) {
                return refuse(414, "the path is longer than " +
                                       std::to_string(preview_limits::kMaxPathBytes) +
                                       " bytes; no such file is served");
            }
            // Refused before httplib reads (and, past its own limit, skips) a declared body.
            if (req.has_header("Content-Length")) {
                const std::string length = req.get_header_value("Content-Length");
                std::uint64_t bytes = 0;
                const auto [end, error] =
                    std::from_chars(length.data(), length.data() + length.size(), bytes);
                if (error != std::errc() || end != length.data() + length.size() ||
                    bytes > preview_limits::kMaxRequestBodyBytes) {
                    return refuse(413, "a request body may have at most " +
                                           std::to_string(preview_limits::kMaxRequestBodyBytes) + " bytes");
                }
            }
            // httplib would answer a Range header of many ranges with that many copies of the file.
            if (req.has_header("Range")) {
                return refuse(416, "ranges are not served; ask for the whole file");
            }
            return httplib::Server::HandlerResponse::Unhandled;
        });
        // Handlers catch everything themselves (guarded); this is for what throws outside them.
        http.set_exception_handler(
            [](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
                std::string message = "internal error";
                try {
                    std::rethrow_exception(ep);
                } catch (const std::exception& e) {
                    message += std::string(": ") + e.what();
                } catch (...) {
                }
                t_close_connection = true;
                send_error(res, 500, message);
            });
        // Every error answer has a body that says what went wrong.
        http.set_error_handler([](const httplib::Request&, httplib::Response& res) {
            if (res.body.empty()) {
                const char* what = res.status == 404   ? "not found"
                                   : res.status == 413 ? "the request is too large"
                                   : res.status == 414 ? "the request line is too long"
                                   : res.status == 400 ? "malformed request"
                                                       : "request refused";
                res.set_content(std::string(what) + "\n", "text/plain");
            }
        });

        http.Get("/api/scene", guarded([this](const httplib::Request&, httplib::Response& res) {
                     send_json(res, state_json());
                 }));

        http.Post("/api/edit", guarded([this](const httplib::Request& req, httplib::Response& res) {
                      if (!json_content_type(req, res)) {
                          return;
                      }
                      session.apply_request(req.body);
                      send_json(res, state_json());
                  }));

        http.Post("/api/focus", guarded([this](const httplib::Request& req, httplib::Response& res) {
                      if (!json_content_type(req, res)) {
                          return;
                      }
                      const nlohmann::json body = parse_request_json(req.body);
                      if (!body.is_object() || !body.contains("x") || !body.contains("y") ||
                          !body["x"].is_number() || !body["y"].is_number()) {
                          send_error(res, 400, "expected {\"x\": pixels, \"y\": pixels}");
                          return;
                      }
                      const auto hit = session.focus_at(body["x"].get<double>(), body["y"].get<double>());
                      if (!hit) {
                          send_json(res, {{"hit", false}});
                          return;
                      }
                      send_json(res, {{"hit", true}, {"distance", hit->distance}, {"depth", hit->depth}});
                  }));

        // Display-only exposure and tone curve (PreviewSession::set_display): {"exposure": stops,
        // "tonemap": "agx"}, or {} for the scene's own. Answers with what frames are now shown through.
        http.Post(
            "/api/display", guarded([this](const httplib::Request& req, httplib::Response& res) {
                if (!json_content_type(req, res)) {
                    return;
                }
                const nlohmann::json body = parse_request_json(req.body);
                const char* expected =
                    "expected {\"exposure\": stops from -64 to 64, \"tonemap\": clamp, reinhard, aces or "
                    "agx} (both, or {} for the scene's own)";
                if (!body.is_object() || (!body.empty() && body.size() != 2)) {
                    send_error(res, 400, expected);
                    return;
                }
                std::optional<DisplayTransform> display;
                if (!body.empty()) {
                    const auto exposure = body.find("exposure");
                    const auto tonemap = body.find("tonemap");
                    if (exposure == body.end() || !exposure->is_number() || tonemap == body.end() ||
                        !tonemap->is_string() || !(std::abs(exposure->get<double>()) <= kMaxExposureStops) ||
                        !tone_curve_table().find(tonemap->get<std::string>())) {
                        send_error(res, 400, expected);
                        return;
                    }
                    display = DisplayTransform{exposure->get<double>(),
                                               tone_curve_table().find(tonemap->get<std::string>())->value};
                }
                session.set_display(display);
                const DisplayTransform now = session.display();
                send_json(res,
                          {{"exposure", now.exposure}, {"tonemap", tone_curve_table().name_of(now.curve)}});
            }));

        // Continuous refinement (PreviewSession::set_continuous): {"continuous": true} refines past the
        // target until told to stop, {"continuous": false} stops at the target reached.
        http.Post("/api/refine", guarded([this](const httplib::Request& req, httplib::Response& res) {
                      if (!json_content_type(req, res)) {
                          return;
                      }
                      const nlohmann::json body = parse_request_json(req.body);
                      if (!body.is_object() || body.size() != 1 || !body.contains("continuous") ||
                          !body["continuous"].is_boolean()) {
                          send_error(res, 400, "expected {\"continuous\": true or false}");
                          return;
                      }
                      session.set_continuous(body["continuous"].get<bool>());
                      send_json(res, {{"continuous", session.continuous()},
                                      {"extendable", session.state().extendable}});
                  }));

        // The latest frame's radiance as the film holds it, as OpenEXR (32-bit float, linear).
        http.Get("/api/image.exr", guarded([this](const httplib::Request&, httplib::Response& res) {
                     auto frame = session.latest_frame();
                     if (!frame || !frame->linear) {
                         send_error(res, 503, "no image yet");
                         return;
                     }
                     res.set_header("Cache-Control", "no-store");
                     res.set_header("Content-Disposition", "attachment; filename=\"glint.exr\"");
                     const std::vector<unsigned char> exr = encode_exr(*frame->linear);
                     res.set_content(reinterpret_cast<const char*>(exr.data()), exr.size(), "image/x-exr");
                 }));

        // A frame's picture, named by the frame event. The latest frame is sent whatever the id asked: a
        // page that asks for a frame already replaced gets the newer one, which it would show next anyway.
        http.Get(R"(/api/frames/(\d{1,20})\.png)",
                 guarded([this](const httplib::Request&, httplib::Response& res) {
                     send_latest_png(res, false);
                 }));
        // Save PNG: the same, as a download.
        http.Get("/api/image.png", guarded([this](const httplib::Request&, httplib::Response& res) {
                     send_latest_png(res, true);
                 }));

        http.Get(
            "/api/scene.yaml", guarded([this](const httplib::Request&, httplib::Response& res) {
                res.set_header("Cache-Control", "no-store");
                res.set_header("Content-Disposition", "attachment; filename=\"scene.yaml\"");
                res.set_content(
                    "# Exported by glint serve: glint render scene.yaml renders this view. Its file paths\n"
                    "# are absolute, so it renders from any folder of this machine.\n" +
                        session.export_yaml(),
                    "application/yaml");
            }));

        http.Get("/api/events", guarded([this](const httplib::Request&, httplib::Response& res) {
                     if (open_streams.fetch_add(1) >= kMaxEventStreams) {
                         open_streams.fetch_sub(1);
                         send_error(res, 503, "too many open event streams");
                         return;
                     }
                     res.set_header("Cache-Control", "no-store");
                     auto seen = std::make_shared<std::uint64_t>(0);
                     res.set_chunked_content_provider(
                         "text/event-stream",
                         // Called by httplib while writing, outside any handler's try: it must not throw.
                         [this, seen](size_t, httplib::DataSink& sink) noexcept {
                             try {
                                 return next_event(*seen, sink);
                             } catch (...) {
                                 return false;  // ends this stream; the others go on
                             }
                         },
                         [this](bool) { open_streams.fetch_sub(1); });
                 }));

        // The page itself: exactly the embedded files, nothing from the disk.
        http.Get(R"(/[^?]*)", guarded([](const httplib::Request& req, httplib::Response& res) {
                     const WebAsset* asset = find_web_asset(req.path);
                     if (!asset) {
                         res.status = 404;
                         res.set_content("not found\n", "text/plain");
                         return;
                     }
                     res.set_header("Cache-Control", "no-cache");
                     res.set_content(asset->bytes.data(), asset->bytes.size(),
                                     std::string(asset->content_type).c_str());
                 }));
    }

    // The latest frame's PNG, written from the frame itself a slice at a time (no copy per request).
    void send_latest_png(httplib::Response& res, bool as_download) {
        auto frame = session.latest_frame();
        if (!frame) {
            send_error(res, 503, "no image yet");
            return;
        }
        res.set_header("Cache-Control", "no-store");
        res.set_header("X-Glint-Frame", std::to_string(frame->id));
        if (as_download) {
            res.set_header("Content-Disposition", "attachment; filename=\"glint.png\"");
        }
        const size_t size = frame->png.size();
        res.set_content_provider(
            size, "image/png",
            [frame = std::move(frame)](size_t offset, size_t length, httplib::DataSink& sink) {
                const size_t slice = std::min(length, kWriteSlice);
                return sink.write(reinterpret_cast<const char*>(frame->png.data()) + offset, slice);
            });
    }

    // Writes the next frame (or a keep-alive comment) to an event stream; false ends the stream.
    bool next_event(std::uint64_t& seen, httplib::DataSink& sink) {
        if (stopping || session.stopping()) {
            sink.done();
            return true;
        }
        const auto frame = session.wait_for_frame(seen, kKeepAliveComment);
        if (stopping || session.stopping()) {
            sink.done();
            return true;
        }
        if (!frame || frame->id == seen) {
            static constexpr char ping[] = ": still here\n\n";  // keeps proxies and the browser content
            return sink.write(ping, sizeof(ping) - 1);
        }
        seen = frame->id;
        // In slices: httplib copies each write twice to frame it as a chunk, and a frame of a large
        // image is megabytes, to every stream at once.
        for (size_t at = 0; at < frame->event.size(); at += kWriteSlice) {
            if (!sink.write(frame->event.data() + at, std::min(kWriteSlice, frame->event.size() - at))) {
                return false;
            }
        }
        return true;
    }
};

PreviewServer::PreviewServer(const SceneDesc& desc, const std::string& display_name,
                             const ConnectionLimits& limits)
    : impl_(std::make_unique<Impl>(desc, display_name, limits)) {
    impl_->routes();
}

PreviewServer::~PreviewServer() {
    stop();
}

int PreviewServer::bind(const std::string& host, int port) {
    impl_->host = host;
    if (port == 0) {
        impl_->port = impl_->http.bind_to_any_port(host);
    } else {
        impl_->port = impl_->http.bind_to_port(host, port) ? port : -1;
    }
    if (impl_->port <= 0) {
        throw std::runtime_error("cannot listen on " + host + ":" + std::to_string(port) +
                                 " (is the port in use, or the address not this machine's?)");
    }
    // The packaged httplib listens with a backlog of 5: many browsers or clients connecting at once
    // would see their connections dropped and retried. listen() again raises it (Linux allows that).
    if (impl_->listen_socket >= 0) {
        ::listen(impl_->listen_socket, SOMAXCONN);
    }
    return impl_->port;
}

void PreviewServer::run() {
    impl_->http.listen_after_bind();
}

void PreviewServer::stop() {
    if (impl_->stopping.exchange(true)) {
        return;
    }
    impl_->session.stop();  // wakes the event streams, which then end
    impl_->http.stop();
}

PreviewSession& PreviewServer::session() {
    return impl_->session;
}

}  // namespace glint
