// `glint serve` left running: no request may crash it, read a file the scene does not refer to, or let
// one client take the server from the others. Each test talks to an in-process server on an ephemeral
// 127.0.0.1 port, with bounded loops and timeouts, and stops by itself.
#include <arpa/inet.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/inotify.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "glint/image/image_io.hpp"
#include "glint/serve/preview_server.hpp"
#include "glint/serve/preview_session.hpp"
#include "glint/serve/scene_edit.hpp"
#include "serve/open_watch.hpp"
#include "test_util.hpp"

namespace glint {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

SceneDesc small_scene() {
    SceneDesc desc = default_scene();
    apply_edits(desc.root, parse_edits(json::parse(R"({"edits": [
        {"path": ["render", "width"], "value": 64}, {"path": ["render", "height"], "value": 36},
        {"path": ["render", "samples"], "value": 4}]})")));
    return desc;
}

// A server on an ephemeral loopback port, served from its own thread, stopped at scope exit.
class RunningServer {
  public:
    explicit RunningServer(const SceneDesc& desc, const ConnectionLimits& limits = {})
        : server_(desc, "test scene", limits) {
        port_ = server_.bind("127.0.0.1", 0);
        thread_ = std::thread([this] { server_.run(); });
        for (int i = 0; i < 200 && !client().Get("/api/scene"); ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    ~RunningServer() {
        server_.stop();
        thread_.join();
    }
    int port() const { return port_; }
    httplib::Client client() const {
        httplib::Client c("127.0.0.1", port_);
        c.set_connection_timeout(2);
        c.set_read_timeout(5);
        return c;
    }
    httplib::Result post_edit(const std::string& body) const {
        return client().Post("/api/edit", body, "application/json");
    }
    json scene() const { return json::parse(client().Get("/api/scene")->body); }

  private:
    PreviewServer server_;
    int port_ = 0;
    std::thread thread_;
};

// A raw TCP connection to the server, closed at scope exit.
class RawSocket {
  public:
    explicit RawSocket(int port) : fd_(::socket(AF_INET, SOCK_STREAM, 0)) {
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_port = htons(static_cast<std::uint16_t>(port));
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0;
    }
    ~RawSocket() { ::close(fd_); }
    RawSocket(const RawSocket&) = delete;
    RawSocket& operator=(const RawSocket&) = delete;

    bool connected() const { return connected_; }
    // Sends all of `bytes` unless the server closes first; returns whether all went.
    bool send(const std::string& bytes) const {
        size_t sent = 0;
        while (sent < bytes.size()) {
            const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
            if (n <= 0) {
                return false;
            }
            sent += static_cast<size_t>(n);
        }
        return true;
    }
    // What arrives until the server closes the connection or `seconds` pass (at most 1 MB).
    std::string read_all(double seconds) const {
        std::string reply;
        const auto until = Clock::now() + std::chrono::duration<double>(seconds);
        char buffer[4096];
        while (reply.size() < (1 << 20)) {
            const auto left =
                std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now()).count();
            pollfd fd{fd_, POLLIN, 0};
            if (left <= 0 || ::poll(&fd, 1, static_cast<int>(left)) <= 0) {
                break;
            }
            const ssize_t n = ::recv(fd_, buffer, sizeof(buffer), 0);
            if (n <= 0) {
                closed_ = true;
                break;
            }
            reply.append(buffer, static_cast<size_t>(n));
        }
        return reply;
    }
    bool closed_by_server() const { return closed_; }
    int fd() const { return fd_; }

  private:
    int fd_;
    bool connected_ = false;
    mutable bool closed_ = false;
};

std::string status_line(const std::string& reply) {
    return reply.substr(0, reply.find("\r\n"));
}

long resident_kb() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmRSS:", 0) == 0) {
            return std::stol(line.substr(6));
        }
    }
    return -1;
}

// --- 1. Costly values --------------------------------------------------------------------------------

TEST(ServeLimits, WhittedWithAHugeMaxDepthIsRefusedAndTheSceneStays) {
    RunningServer server(small_scene());
    auto res = server.post_edit(R"({"edits": [{"path": ["render", "integrator"], "value": "whitted"},
                                             {"path": ["render", "max_depth"], "value": 100000000}]})");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 422);
    const json reply = json::parse(res->body);
    EXPECT_EQ(reply["key"], "render.max_depth");
    EXPECT_EQ(reply["value"], 1e8);
    EXPECT_EQ(reply["maximum"], 64);
    EXPECT_NE(reply["error"].get<std::string>().find("at most 64"), std::string::npos);
    const json state = server.scene();
    EXPECT_EQ(state["generation"], 1);
    EXPECT_EQ(state["settings"]["integrator"], "raycast");
    EXPECT_EQ(state["limits"]["max_depth"], 64);
    // At the limit it renders.
    res = server.post_edit(R"({"edits": [{"path": ["render", "integrator"], "value": "whitted"},
                                        {"path": ["render", "max_depth"], "value": 64}]})");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 200) << res->body;
}

TEST(ServeLimits, BadValuesAndBodiesAreClean4xxAndChangeNothing) {
    RunningServer server(small_scene());
    struct Case {
        std::string body;
        int status;
        std::string message_part;
    };
    const std::string deep = std::string(20000, '[') + std::string(20000, ']');
    const std::vector<Case> cases = {
        {R"({"path": ["render", "width"], "value": 5000})", 422, "render.width is 5000"},
        {R"({"path": ["render", "samples"], "value": 1e12})", 422, "at most 16384"},
        {R"({"path": ["render", "max_depth"], "value": 18446744073709551615})", 422, "at most 64"},
        {R"({"path": ["camera", "fov"], "value": NaN})", 400, "not valid JSON"},
        {R"({"path": ["camera", "fov"], "value": 1e999})", 400, "number overflow"},
        {R"({"path": ["camera", "fov"], "value": "inf"})", 422, "finite"},
        {R"({"path": ["render", "max_depth"], "value": -3})", 422, "max_depth"},
        {R"({"path": ["render", "samples"], "value": "many"})", 422, "samples"},
        {R"({"path": ["camera", "type"], "value": ")" + std::string(60000, 'x') + R"("})", 400, "one word"},
        {R"({"path": ["camera", "type"], "value": ")" + std::string(63, 'a') + "\xc3\xa9" + R"("})", 400,
         "one word"},
        {deep, 400, "nested more than 8"},
        {R"({"path": ["camera", "eye"], "value": )" + deep + "}", 400, "nested more than 8"},
    };
    for (const Case& c : cases) {
        auto res = server.post_edit(c.body);
        ASSERT_TRUE(res) << c.body.substr(0, 80);
        EXPECT_EQ(res->status, c.status) << c.body.substr(0, 80) << " → " << res->body.substr(0, 200);
        const json reply = json::parse(res->body, nullptr, false);
        ASSERT_TRUE(reply.is_object() && reply.contains("error")) << res->body.substr(0, 200);
        EXPECT_NE(reply["error"].get<std::string>().find(c.message_part), std::string::npos)
            << reply["error"];
    }
    // Over the body limit: 413, whether the size is declared or not.
    auto res = server.post_edit(std::string(70 * 1024, ' '));
    if (res) {
        EXPECT_EQ(res->status, 413);
    }
    EXPECT_EQ(server.client().Post("/api/focus", deep, "application/json")->status, 400);

    const json state = server.scene();
    EXPECT_EQ(state["generation"], 1);
    EXPECT_EQ(state["scene"]["render"]["width"], 64);
}

// --- 2. Files ---------------------------------------------------------------------------------------------

TEST(ServeLimits, AnEditNamingAnyFileGetsTheSameAnswerAndOpensNothing) {
    test::TempDir dir;
    Image texture(2, 2);
    const std::vector<unsigned char> png = encode_png(texture);
    std::ofstream(dir / "tex.png", std::ios::binary)
        .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    dir.write("secret", "not for the browser\n");
    dir.write("scene.yaml", R"(
render: {width: 32, height: 18, samples: 1}
materials:
  wood: {type: matte, albedo: {type: image, file: tex.png}}
  red: {type: matte, albedo: [0.8, 0.1, 0.1]}
objects:
  - {type: sphere, radius: 1, material: wood}
)");
    RunningServer server(load_scene_file(dir / "scene.yaml"));

    // Watch the folder for any file being opened from now on.
    test::OpenWatch watch(dir.path(), IN_OPEN | IN_ACCESS);
    const auto opened = [&] { return watch.opened(); };

    const auto new_texture = [&](const std::string& file) {
        return server.post_edit(R"({"edits": [{"path": ["materials", "red", "albedo"], "value": null},
                                              {"path": ["materials", "red", "albedo", "type"], "value": "image"},
                                              {"path": ["materials", "red", "albedo", "file"], "value": ")" +
                                file + R"("}]})");
    };
    const auto existing = new_texture("secret");
    const auto missing = new_texture("nosuchfile");
    ASSERT_TRUE(existing && missing);
    EXPECT_EQ(existing->status, 403);
    EXPECT_EQ(existing->status, missing->status);
    EXPECT_EQ(existing->body, missing->body);
    EXPECT_EQ(existing->get_header_value("Content-Type"), missing->get_header_value("Content-Type"));
    EXPECT_EQ(existing->get_header_value("Content-Length"), missing->get_header_value("Content-Length"));
    EXPECT_EQ(json::parse(existing->body)["error"], kFileReferenceRefused);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_EQ(opened(), std::vector<std::string>{});
    EXPECT_EQ(server.scene()["generation"], 1);

    // A camera edit keeps the built world: no file is read.
    auto res = server.post_edit(R"({"path": ["camera", "fov"], "value": 30})");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 200) << res->body;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_EQ(opened(), std::vector<std::string>{});

    // The watch does see opens: an accepted edit of the world rebuilds its materials, which read the
    // scene's texture.
    res = server.post_edit(R"({"path": ["background"], "value": [0.1, 0.1, 0.1]})");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 200) << res->body;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const std::vector<std::string> after = opened();
    EXPECT_NE(std::find(after.begin(), after.end(), "tex.png"), after.end());
    EXPECT_EQ(std::find(after.begin(), after.end(), "secret"), after.end());
}

// --- 3. Slow and greedy clients -----------------------------------------------------------------------

TEST(ServeLimits, FiftySlowClientsDoNotKeepAnotherWaiting) {
    RunningServer server(small_scene());
    std::vector<std::unique_ptr<RawSocket>> idle, trickling;
    for (int i = 0; i < 25; ++i) {
        idle.push_back(std::make_unique<RawSocket>(server.port()));
        trickling.push_back(std::make_unique<RawSocket>(server.port()));
        ASSERT_TRUE(idle.back()->connected() && trickling.back()->connected());
    }
    // The trickling ones send a request a byte at a time, for 1.5 s.
    std::atomic<bool> done{false};
    std::thread trickle([&] {
        const std::string request = "GET /api/scene HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow: ";
        for (size_t i = 0; !done && i < 30; ++i) {
            for (auto& socket : trickling) {
                socket->send(std::string(1, request[i % request.size()]));
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    for (int i = 0; i < 5; ++i) {
        const auto start = Clock::now();
        auto res = server.client().Get("/api/scene");
        ASSERT_TRUE(res);
        EXPECT_EQ(res->status, 200);
        EXPECT_LT(seconds_since(start), 2.0);
    }
    done = true;
    trickle.join();
}

TEST(ServeLimits, IdleAndTricklingClientsAreCutOff) {
    ConnectionLimits limits;
    limits.idle_timeout = std::chrono::milliseconds(300);
    limits.read_timeout = std::chrono::milliseconds(500);
    limits.request_deadline = std::chrono::milliseconds(800);
    RunningServer server(small_scene(), limits);

    // Connects and says nothing: closed after the idle timeout.
    RawSocket idle(server.port());
    auto start = Clock::now();
    EXPECT_EQ(idle.read_all(3.0), "");
    EXPECT_TRUE(idle.closed_by_server());
    EXPECT_GT(seconds_since(start), 0.2);
    EXPECT_LT(seconds_since(start), 1.5);

    // Sends a byte every 100 ms, never pausing long: refused when the whole request is late.
    RawSocket trickling(server.port());
    start = Clock::now();
    std::string reply;
    for (int i = 0; i < 40 && reply.empty(); ++i) {
        if (!trickling.send("G")) {
            break;
        }
        reply = trickling.read_all(0.1);
    }
    reply += trickling.read_all(1.0);
    EXPECT_EQ(status_line(reply), "HTTP/1.1 408 Request Timeout") << reply.substr(0, 200);
    EXPECT_GT(seconds_since(start), 0.7);
    EXPECT_LT(seconds_since(start), 2.0);

    // Pauses longer than the read timeout mid-request: refused too.
    RawSocket pausing(server.port());
    ASSERT_TRUE(pausing.send("GET / HTTP/1.1\r\n"));
    EXPECT_EQ(status_line(pausing.read_all(2.0)), "HTTP/1.1 408 Request Timeout");
    EXPECT_EQ(server.client().Get("/api/scene")->status, 200);
}

TEST(ServeLimits, ConnectionsPastTheCapAreRefusedAtOnce) {
    ConnectionLimits limits;
    limits.max_connections = 4;
    limits.idle_timeout = std::chrono::milliseconds(5000);
    RunningServer server(small_scene(), limits);
    std::vector<std::unique_ptr<RawSocket>> held;
    for (int i = 0; i < limits.max_connections; ++i) {
        held.push_back(std::make_unique<RawSocket>(server.port()));
    }
    // The held connections count once the server has accepted them, which a loaded machine may take
    // a moment to do: ask until the answer is the refusal (a request before that is answered normally).
    int refusal_status = 0;
    std::string refusal_body;
    double refusal_seconds = 0;
    for (const auto until = Clock::now() + std::chrono::seconds(5); Clock::now() < until;) {
        const auto asked = Clock::now();
        const auto res = server.client().Get("/api/scene");
        refusal_seconds = seconds_since(asked);
        refusal_status = res ? res->status : 0;
        if (refusal_status == 503) {
            refusal_body = res->body;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_EQ(refusal_status, 503);
    EXPECT_NE(json::parse(refusal_body)["error"].get<std::string>().find("too many open connections"),
              std::string::npos);
    EXPECT_LT(refusal_seconds, 1.0);  // refused at once, not after a wait for a free slot

    held.clear();  // the server notices the closes within its wait slice
    const auto start = Clock::now();
    int status = 0;
    while (status != 200 && seconds_since(start) < 2.0) {
        auto again = server.client().Get("/api/scene");
        status = again ? again->status : 0;
    }
    EXPECT_EQ(status, 200);
}

TEST(ServeLimits, OversizedHeadsAndBodiesAreRefusedBeforeTheyAreStored) {
    RunningServer server(small_scene());
    const auto reply_to = [&](const std::string& request, bool may_close = false) {
        RawSocket socket(server.port());
        const bool all_sent = socket.send(request);
        const std::string reply = socket.read_all(3.0);
        if (reply.empty() && may_close && !all_sent) {
            return std::string("closed");
        }
        return status_line(reply);
    };
    const std::string get = "GET /api/scene HTTP/1.1\r\nHost: 127.0.0.1\r\n";

    std::string many_headers = get;
    for (int i = 0; i < 65; ++i) {
        many_headers += "X-H" + std::to_string(i) + ": v\r\n";
    }
    EXPECT_EQ(reply_to(many_headers + "\r\n"), "HTTP/1.1 431 Request Header Fields Too Large");
    std::string thousands = get;
    for (int i = 0; i < 5000; ++i) {
        thousands += "X-H" + std::to_string(i) + ": v\r\n";
    }
    const std::string thousands_reply = reply_to(thousands + "\r\n", true);
    EXPECT_TRUE(thousands_reply == "HTTP/1.1 431 Request Header Fields Too Large" ||
                thousands_reply == "closed")
        << thousands_reply;
    EXPECT_EQ(reply_to(get + "X-Big: " + std::string(20000, 'b') + "\r\n\r\n"),
              "HTTP/1.1 431 Request Header Fields Too Large");

    // Bodies past the limit, however they are framed.
    const std::string post =
        "POST /api/edit HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n";
    std::string chunked = post + "Transfer-Encoding: chunked\r\n\r\n";
    for (int i = 0; i < 64; ++i) {
        chunked += "4000\r\n" + std::string(0x4000, ' ') + "\r\n";
    }
    const std::string chunked_reply = reply_to(chunked + "0\r\n\r\n", true);
    EXPECT_TRUE(chunked_reply == "HTTP/1.1 413 Payload Too Large" || chunked_reply == "closed")
        << chunked_reply;
    const std::string unframed_reply = reply_to(post + "\r\n" + std::string(1 << 20, ' '), true);
    EXPECT_TRUE(unframed_reply == "HTTP/1.1 413 Payload Too Large" || unframed_reply == "closed")
        << unframed_reply;
    const std::string declared_reply =
        reply_to(post + "Content-Length: 10000000000\r\n\r\n" + std::string(1 << 20, ' '), true);
    EXPECT_TRUE(declared_reply == "HTTP/1.1 413 Payload Too Large" || declared_reply == "closed")
        << declared_reply;
    EXPECT_EQ(reply_to(post + "Content-Length: 70000\r\n\r\n"), "HTTP/1.1 413 Payload Too Large");

    // Eight clients each pour 16 MB of headers in: the server stops reading each at 16 KB, so its
    // memory does not follow (httplib alone would have stored every header).
    const long before = resident_kb();
    std::vector<std::thread> pourers;
    std::atomic<long> poured{0};
    std::atomic<int> poured_all{0};
    for (int i = 0; i < 8; ++i) {
        pourers.emplace_back([&] {
            RawSocket socket(server.port());
            std::string chunk;
            while (chunk.size() < 64 * 1024) {
                chunk += "X-Flood: " + std::to_string(chunk.size()) + "\r\n";
            }
            socket.send(get);
            int k = 0;
            for (; k < 256 && socket.send(chunk); ++k) {
                poured += static_cast<long>(chunk.size());
            }
            poured_all += k == 256 ? 1 : 0;
        });
    }
    for (auto& t : pourers) {
        t.join();
    }
    const long after = resident_kb();
    EXPECT_LT(after - before, 32 * 1024) << "kB; poured " << poured.load() / 1024 << " kB";
    EXPECT_EQ(poured_all.load(), 0);  // every pourer was cut off
    EXPECT_EQ(server.client().Get("/api/scene")->status, 200);
}

TEST(ServeLimits, RangesAndLongPathsAreRefusedAndPipelinedRequestsAnswered) {
    RunningServer server(small_scene());
    httplib::Headers range = {{"Range", "bytes=0-0,0-0,0-0"}};
    auto res = server.client().Get("/app.js", range);
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 416);
    const std::string long_path(301, '/');  // "///…": a path of 301 bytes
    res = server.client().Get(long_path);
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 414);

    RawSocket socket(server.port());
    ASSERT_TRUE(
        socket.send("GET /api/scene HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n"
                    "GET /style.css HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n"));
    const std::string replies = socket.read_all(3.0);
    EXPECT_EQ(replies.rfind("HTTP/1.1 200 OK", 0), 0u);
    EXPECT_NE(replies.find("HTTP/1.1 200 OK", 10), std::string::npos) << replies.size();
    EXPECT_TRUE(socket.closed_by_server());
}

// A client may half-close its side once the request is sent (`nc -N`, `curl` behind some proxies):
// it still gets the answer.
TEST(ServeLimits, AClientThatHalfClosesAfterItsRequestStillGetsTheAnswer) {
    RunningServer server(small_scene());
    RawSocket socket(server.port());
    ASSERT_TRUE(socket.send("GET /api/scene HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n"));
    ASSERT_EQ(::shutdown(socket.fd(), SHUT_WR), 0);
    const std::string reply = socket.read_all(3.0);
    EXPECT_EQ(status_line(reply), "HTTP/1.1 200 OK") << reply.substr(0, 200);
}

}  // namespace
}  // namespace glint
