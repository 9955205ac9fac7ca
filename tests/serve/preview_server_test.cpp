// The preview server, in-process on an ephemeral loopback port, driven with httplib::Client: what it
// serves, what it refuses (malformed, oversized, traversal, foreign hosts), edits restarting the
// accumulation, many clients at once, and a clean shutdown with streams open.
#include "glint/serve/preview_server.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>

#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>
#include "glint/sampling/sampler.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <nlohmann/json.hpp>
#include <thread>

#include "glint/image/image_io.hpp"
#include "glint/light/light.hpp"
#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/serve/preview_session.hpp"
#include "glint/serve/scene_edit.hpp"

namespace glint {
namespace {

using nlohmann::json;

SceneDesc small_scene() {
    SceneDesc desc = default_scene();
    apply_edits(desc.root, parse_edits(json::parse(R"({"edits": [
        {"path": ["render", "width"], "value": 64}, {"path": ["render", "height"], "value": 36},
        {"path": ["render", "samples"], "value": 16}]})")));
    return desc;
}

class PreviewServerTest : public ::testing::Test {
  protected:
    void SetUp() override {
        server_ = std::make_unique<PreviewServer>(small_scene(), "test scene");
        port_ = server_->bind("127.0.0.1", 0);
        thread_ = std::thread([this] { server_->run(); });
        // Wait until it answers.
        for (int i = 0; i < 200 && !client().Get("/api/scene"); ++i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    void TearDown() override {
        server_->stop();
        thread_.join();
    }
    httplib::Client client() const {
        httplib::Client c("127.0.0.1", port_);
        c.set_connection_timeout(2);
        c.set_read_timeout(5);
        return c;
    }
    httplib::Result post(const std::string& path, const std::string& body,
                         const std::string& type = "application/json") const {
        return client().Post(path.c_str(), body, type.c_str());
    }
    // Sends raw bytes and returns the reply's status line and headers (or what came before the
    // connection's end or 2 s).
    std::string raw(const std::string& bytes) const {
        const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in addr{};
        addr.sin_family = AF_INET;
        addr.sin_port = htons(static_cast<std::uint16_t>(port_));
        addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        EXPECT_EQ(::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)), 0);
        timeval timeout{2, 0};
        ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof(timeout));
        size_t sent = 0;
        while (sent < bytes.size()) {
            const ssize_t n = ::send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
            if (n <= 0) {
                break;  // the server may close early on a request it refuses
            }
            sent += static_cast<size_t>(n);
        }
        std::string reply;
        char buffer[4096];
        for (ssize_t n; reply.find("\r\n\r\n") == std::string::npos &&
                        (n = ::recv(fd, buffer, sizeof(buffer), 0)) > 0;) {
            reply.append(buffer, static_cast<size_t>(n));
        }
        ::close(fd);
        return reply;
    }
    // Reads "frame" events until `done(frame)` says stop; returns false on a timeout or a closed stream.
    bool read_frames(const std::function<bool(const json&)>& done, int seconds = 10) const {
        httplib::Client c = client();
        c.set_read_timeout(seconds);
        std::string buffer;
        bool finished = false;
        const auto start = std::chrono::steady_clock::now();
        c.Get("/api/events", [&](const char* data, size_t size) {
            buffer.append(data, size);
            for (size_t end; (end = buffer.find("\n\n")) != std::string::npos;) {
                const std::string event = buffer.substr(0, end);
                buffer.erase(0, end + 2);
                const size_t data_at = event.find("data: ");
                if (event.rfind("event: frame", 0) == 0 && data_at != std::string::npos &&
                    done(json::parse(event.substr(data_at + 6)))) {
                    finished = true;
                    return false;
                }
            }
            return std::chrono::steady_clock::now() - start < std::chrono::seconds(seconds);
        });
        return finished;
    }

    std::unique_ptr<PreviewServer> server_;
    int port_ = 0;
    std::thread thread_;
};

TEST_F(PreviewServerTest, ServesTheEmbeddedPageAndNothingElse) {
    auto page = client().Get("/");
    ASSERT_TRUE(page);
    EXPECT_EQ(page->status, 200);
    EXPECT_NE(page->body.find("<!doctype html>"), std::string::npos);
    EXPECT_EQ(page->get_header_value("Content-Type"), "text/html; charset=utf-8");
    auto script = client().Get("/app.js");
    ASSERT_TRUE(script);
    EXPECT_EQ(script->status, 200);
    EXPECT_EQ(script->get_header_value("Content-Type"), "text/javascript; charset=utf-8");
    EXPECT_EQ(client().Get("/style.css")->status, 200);

    for (const char* path :
         {"/../CMakeLists.txt", "/../../../../etc/passwd", "/%2e%2e/%2e%2e/etc/passwd", "/web/index.html",
          "/index.html/../../etc/passwd", "//etc/passwd", "/api/../../etc/passwd", "/..%2f..%2fetc%2fpasswd",
          "/.%2e/CMakeLists.txt", "/app.js%00.html", "/nothing"}) {
        auto res = client().Get(path);
        ASSERT_TRUE(res) << path;
        EXPECT_EQ(res->status, 404) << path;
        EXPECT_EQ(res->body.find("root:"), std::string::npos) << path;
    }
    // The same through a raw socket, where no client library tidies the path.
    const std::string reply =
        raw("GET /../../../../etc/passwd HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n");
    EXPECT_EQ(reply.rfind("HTTP/1.1 404", 0), 0u) << reply.substr(0, 80);
}

TEST_F(PreviewServerTest, SceneIsSentAsJsonWithTheTablesNames) {
    auto res = client().Get("/api/scene");
    ASSERT_TRUE(res);
    ASSERT_EQ(res->status, 200);
    const json state = json::parse(res->body);
    EXPECT_EQ(state["scene"]["render"]["width"], 64);
    EXPECT_EQ(state["scene"]["camera"]["eye"], json::parse("[0, 1.6, 7]"));
    EXPECT_EQ(state["scene"]["materials"]["red"]["type"], "matte");
    // The page's menus are the sampler table, in its order.
    const std::vector<std::string> names = glint::sampler_table().names();
    ASSERT_EQ(state["samplers"].size(), names.size());
    for (size_t i = 0; i < names.size(); ++i) {
        EXPECT_EQ(state["samplers"][i]["name"], names[i]);
    }
    EXPECT_FALSE(state["integrators"].empty());
    // The light panel's type menu is the light table.
    EXPECT_EQ(state["light_types"].get<std::vector<std::string>>(), glint::light_table().names());
    EXPECT_EQ(state["scene"]["lights"][1]["intensity"], 90);
    EXPECT_EQ(state["width"], 64);
}

TEST_F(PreviewServerTest, MalformedRequestsGetA4xxWithAMessage) {
    struct Case {
        std::string body, type;
        int status;
        std::string message_part;
    };
    const std::vector<Case> cases = {
        {"{not json", "application/json", 400, "not valid JSON"},
        {R"({"path": ["render", "width"], "value": 10})", "text/plain", 415, "application/json"},
        {"[]", "application/json", 400, "JSON object"},
        {R"({"path": "render.width", "value": 1})", "application/json", 400, "list of 1 to"},
        {R"({"path": ["objects", "0"], "value": 1})", "application/json", 400, "cannot be edited"},
        {R"({"path": ["materials", "red"], "value": 1})", "application/json", 400, "materials.<name>"},
        {R"({"path": ["materials", "nope", "albedo"], "value": 1})", "application/json", 400,
         "no material 'nope'"},
        {R"({"path": ["camera", "eye"], "value": {"x": 1}})", "application/json", 400, "must be a number"},
        {R"({"path": ["camera", "type"], "value": "../../etc/passwd"})", "application/json", 400, "one word"},
        {R"({"path": ["camera", "eye"], "value": ["a", 1, 2]})", "application/json", 400, "numbers only"},
        {R"({"path": ["camera", "look_at"], "value": [0, 1.6, 7]})", "application/json", 422, "must differ"},
        {R"({"path": ["render", "sampler"], "value": "jitterd"})", "application/json", 422,
         "did you mean 'jittered'"},
        {R"({"edits": [{"path": ["render", "width"], "value": 30000}, {"path": ["render", "height"], "value": 30000}]})",
         "application/json", 422, "at most 4096"},
        {R"({"path": ["render", "width"], "value": -5})", "application/json", 422, "render"},
        {R"({"path": ["render", "widht"], "value": 5})", "application/json", 422, "did you mean 'width'"},
        {R"({"edits": []})", "application/json", 400, "non-empty"},
        // Objects and lights by position: an inline material's or a light's parameter only.
        {R"({"path": ["objects", 1, "radius"], "value": 2})", "application/json", 400, "inline material"},
        {R"({"path": ["objects", 1, "material", "albedo"], "value": 0.5})", "application/json", 400,
         "materials.red.albedo"},
        {R"({"path": ["lights", 3, "intensity"], "value": 5})", "application/json", 400,
         "there is no light 3"},
        {R"({"path": ["lights", 1, "intensity"], "value": -5})", "application/json", 422, "intensity"},
        {R"({"path": ["lights", 1, "positon"], "value": [0, 1, 0]})", "application/json", 422,
         "did you mean 'position'"},
    };
    for (const Case& c : cases) {
        auto res = post("/api/edit", c.body, c.type);
        ASSERT_TRUE(res) << c.body;
        EXPECT_EQ(res->status, c.status) << c.body << " → " << res->body;
        const json reply = json::parse(res->body, nullptr, false);
        ASSERT_TRUE(reply.contains("error")) << res->body;
        EXPECT_NE(reply["error"].get<std::string>().find(c.message_part), std::string::npos)
            << reply["error"];
    }
    // Nothing of that changed the scene.
    const json state = json::parse(client().Get("/api/scene")->body);
    EXPECT_EQ(state["generation"], 1);
    EXPECT_EQ(state["scene"]["render"]["width"], 64);

    EXPECT_EQ(post("/api/focus", R"({"x": "middle"})")->status, 400);
    EXPECT_EQ(client().Post("/api/scene", "", "application/json")->status, 404);

    // Not HTTP at all: a 400, and the server goes on.
    const std::string reply = raw("HELLO THERE\r\n\r\n");
    EXPECT_EQ(reply.rfind("HTTP/1.1 400", 0), 0u) << reply.substr(0, 80);
    EXPECT_EQ(client().Get("/api/scene")->status, 200);
}

TEST_F(PreviewServerTest, OversizedRequestsAreRefused) {
    const std::string big(2 * 1024 * 1024, ' ');
    auto res = post("/api/edit", big);
    // Either a 413, or the connection is closed before the whole body is sent.
    if (res) {
        EXPECT_EQ(res->status, 413);
    }
    // Past httplib's 8192-byte request line, within the 16 KiB of a request's head: httplib's 414.
    const std::string long_uri =
        raw("GET /" + std::string(10000, 'a') + " HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
    EXPECT_EQ(long_uri.rfind("HTTP/1.1 414", 0), 0u) << long_uri.substr(0, 80);
    // Past the head's 16 KiB: refused before httplib stores it.
    const std::string long_header =
        raw("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Big: " + std::string(20000, 'b') + "\r\n\r\n");
    EXPECT_EQ(long_header.rfind("HTTP/1.1 431", 0), 0u) << long_header.substr(0, 80);
    EXPECT_EQ(client().Get("/api/scene")->status, 200);
}

TEST_F(PreviewServerTest, ForeignHostNamesAreRefused) {
    httplib::Headers headers = {{"Host", "attacker.example:80"}};
    auto res = client().Get("/api/scene", headers);
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 403);
    headers = {{"Host", "localhost:" + std::to_string(port_)}};
    EXPECT_EQ(client().Get("/api/scene", headers)->status, 200);
}

TEST_F(PreviewServerTest, FramesRefineAndAnEditRestartsTheAccumulation) {
    // The first generation refines to its 16 samples per pixel.
    ASSERT_TRUE(read_frames([](const json& f) { return f["generation"] == 1 && f["samples"] == 16; }));

    auto res =
        post("/api/edit", R"({"edits": [{"path": ["materials", "red", "albedo"], "value": [0.1, 0.9, 0.1]},
                                               {"path": ["render", "samples"], "value": 64}]})");
    ASSERT_TRUE(res);
    ASSERT_EQ(res->status, 200) << res->body;
    EXPECT_EQ(json::parse(res->body)["generation"], 2);

    std::vector<int> samples;
    std::string first_png;
    ASSERT_TRUE(read_frames([&](const json& f) {
        if (f["generation"] != 2) {
            return false;
        }
        samples.push_back(f["samples"]);
        EXPECT_EQ(f["target"], 64);
        EXPECT_EQ(f["width"], 64);
        EXPECT_GE(f["mrays_per_second"].get<double>(), 0.0);
        EXPECT_FALSE(f.contains("png"));  // the picture travels as binary, fetched from "image"
        EXPECT_EQ(f["image"], "/api/frames/" + std::to_string(f["id"].get<std::uint64_t>()) + ".png");
        return f["samples"] == 64;
    }));
    // The stream sends the latest frame, so early passes may be skipped; the last is complete.
    EXPECT_EQ(samples.back(), 64);

    // The frame's own address serves the binary PNG of the latest frame (no base64), the same bytes as
    // the Save PNG download.
    const auto latest = server_->session().latest_frame();
    auto framed = client().Get(("/api/frames/" + std::to_string(latest->id) + ".png").c_str());
    ASSERT_TRUE(framed);
    EXPECT_EQ(framed->status, 200);
    EXPECT_EQ(framed->get_header_value("Content-Type"), "image/png");
    EXPECT_TRUE(framed->body == std::string(latest->png.begin(), latest->png.end()));
    EXPECT_EQ(client().Get("/api/frames/x.png")->status, 404);

    // The image download is the complete picture of the new scene.
    auto image = client().Get("/api/image.png");
    ASSERT_TRUE(image);
    EXPECT_EQ(image->status, 200);
    EXPECT_EQ(image->body.substr(1, 3), "PNG");

    // The exported YAML holds the edit and parses back to the scene on screen.
    auto yaml = client().Get("/api/scene.yaml");
    ASSERT_TRUE(yaml);
    const SceneDesc exported = parse_scene_text(yaml->body, "export", ".");
    EXPECT_EQ(exported.root.find("materials")->find("red")->find("albedo")->items[1].scalar, "0.9");
    EXPECT_EQ(exported.root.find("render")->find("samples")->scalar, "64");

    // Nothing of the first picture is left: the image is, bit for bit, a fresh render of the exported
    // scene (which also shows that export renders what is on screen).
    const Scene scene = build_scene(exported);
    Film film(scene.view.settings.width, scene.view.settings.height);
    render(scene, film);
    const std::vector<unsigned char> expected = encode_png(film.to_image(), kPngFrameEncoding);
    EXPECT_TRUE(image->body == std::string(expected.begin(), expected.end()));
}

// Frames of a generation only ever add samples, up to the target. (That the first one is coarse is
// checked by the browser test and by ProgressiveRender's tests: a waiter sees only the latest frame,
// so here it may miss the early ones.)
TEST_F(PreviewServerTest, AChangeRefinesMonotonicallyToTheNewTarget) {
    server_->session().apply(parse_edits(json::parse(R"({"path": ["render", "width"], "value": 320})")));
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    std::uint64_t seen = 0;
    std::vector<std::uint32_t> samples;
    while (std::chrono::steady_clock::now() < deadline && (samples.empty() || samples.back() != 16)) {
        const auto frame = server_->session().wait_for_frame(seen, std::chrono::milliseconds(200));
        if (frame && frame->id != seen) {
            seen = frame->id;
            if (frame->generation == 2) {
                EXPECT_EQ(frame->width, 320);
                samples.push_back(frame->samples);
            }
        }
    }
    ASSERT_FALSE(samples.empty());
    EXPECT_EQ(samples.back(), 16u);
    EXPECT_TRUE(std::is_sorted(samples.begin(), samples.end()));
}

TEST_F(PreviewServerTest, ClickToFocusGivesTheDistanceToTheHit) {
    // The centre pixel looks from eye (0, 1.6, 7) at (0, 0.8, 0) and meets the unit sphere at (0, 1, 0).
    auto res = post("/api/focus", R"({"x": 32, "y": 18})");
    ASSERT_TRUE(res);
    ASSERT_EQ(res->status, 200);
    const json hit = json::parse(res->body);
    ASSERT_TRUE(hit["hit"].get<bool>());
    const double dy = -0.8, dz = -7, norm = std::sqrt(dy * dy + dz * dz);
    const double ocy = 0.6, ocz = 7;  // eye − centre
    const double b = (ocy * dy + ocz * dz) / norm, c = ocy * ocy + ocz * ocz - 1;
    const double expected = -b - std::sqrt(b * b - c);
    EXPECT_NEAR(hit["distance"].get<double>(), expected, 1e-9);
    EXPECT_NEAR(hit["depth"].get<double>(), expected, 1e-9);  // on the axis, depth = distance
    // Towards the sky: no hit.
    EXPECT_FALSE(json::parse(post("/api/focus", R"({"x": 32, "y": 0})")->body)["hit"].get<bool>());
    EXPECT_FALSE(json::parse(post("/api/focus", R"({"x": -3, "y": 1e300})")->body)["hit"].get<bool>());
}

TEST_F(PreviewServerTest, FiftyClientsAtOnceAreAllServed) {
    constexpr int kClients = 50;
    std::atomic<int> answered{0}, refused{0}, failed{0};
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(800);
    std::vector<std::thread> clients;
    for (int i = 0; i < kClients; ++i) {
        clients.emplace_back([&, i] {
            int round = 0;
            while (std::chrono::steady_clock::now() < until) {
                httplib::Client c = client();
                bool got_frame = false;
                const int kind = (i + round++) % 5;
                const auto t0 = std::chrono::steady_clock::now();
                httplib::Result res = [&] {
                    switch (kind) {
                        case 0:
                            return c.Get("/api/scene");
                        case 1:
                            return c.Get("/");
                        case 2:
                            return c.Post("/api/edit",
                                          json{{"path", {"camera", "fov"}}, {"value", 30 + (i % 10)}}.dump(),
                                          "application/json");
                        case 3:
                            return c.Post("/api/edit", "{broken", "application/json");
                        default:
                            // An event stream, read for one frame then dropped.
                            return c.Get("/api/events", [&](const char* data, size_t size) {
                                got_frame = std::string_view(data, size).find("event: frame") !=
                                            std::string_view::npos;
                                return !got_frame;
                            });
                    }
                }();
                if (got_frame) {
                    ++answered;
                    continue;
                }
                if (!res) {
                    std::fprintf(
                        stderr, "client %d kind %d: %s after %.3f s\n", i, kind,
                        httplib::to_string(res.error()).c_str(),
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
                    ++failed;
                } else if (res->status == 503) {
                    ++refused;
                } else {
                    ++answered;
                }
            }
        });
    }
    for (auto& t : clients) {
        t.join();
    }
    EXPECT_EQ(failed.load(), 0);
    EXPECT_GE(answered.load(), kClients);
    auto res = client().Get("/api/scene");
    ASSERT_TRUE(res);
    EXPECT_EQ(res->status, 200);
}

// Event streams hold a thread each while open; past the cap they are refused, and ordinary requests
// are still answered at once.
TEST_F(PreviewServerTest, EventStreamsCannotStarveTheServer) {
    std::atomic<bool> release{false};
    std::atomic<int> streaming{0};
    std::vector<std::thread> watchers;
    for (int i = 0; i < PreviewServer::kMaxEventStreams; ++i) {
        watchers.emplace_back([&] {
            httplib::Client c = client();
            bool counted = false;
            c.Get("/api/events", [&](const char*, size_t) {
                if (!counted) {
                    counted = true;
                    ++streaming;
                }
                return !release.load();
            });
        });
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    while (streaming.load() < PreviewServer::kMaxEventStreams &&
           std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_EQ(streaming.load(), PreviewServer::kMaxEventStreams);
    auto refused = client().Get("/api/events");
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->status, 503);
    const auto start = std::chrono::steady_clock::now();
    auto scene = client().Get("/api/scene");
    ASSERT_TRUE(scene);
    EXPECT_EQ(scene->status, 200);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
    release = true;
    server_->stop();  // wakes the streams, which end
    for (auto& t : watchers) {
        t.join();
    }
}

TEST_F(PreviewServerTest, StopEndsOpenEventStreams) {
    std::vector<std::thread> watchers;
    std::atomic<int> ended{0};
    for (int i = 0; i < 4; ++i) {
        watchers.emplace_back([&] {
            httplib::Client c = client();
            c.set_read_timeout(30);
            c.Get("/api/events", [](const char*, size_t) { return true; });
            ++ended;
        });
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    const auto start = std::chrono::steady_clock::now();
    server_->stop();
    for (auto& t : watchers) {
        t.join();
    }
    EXPECT_EQ(ended.load(), 4);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(3));
}

}  // namespace
}  // namespace glint

namespace glint {
namespace {

TEST_F(PreviewServerTest, SaveExrGivesTheFilmsRadianceAsItIsAndTheDisplayControlsOnlyTheView) {
    // Wait for the finished render: its EXR is the film of `glint render` at 16 spp, bit for bit.
    ASSERT_TRUE(read_frames([](const json& f) { return f["samples"] == f["target"]; }));
    const auto exr = client().Get("/api/image.exr");
    ASSERT_TRUE(exr);
    ASSERT_EQ(exr->status, 200);
    const std::vector<unsigned char> bytes(exr->body.begin(), exr->body.end());
    const Image served = decode_image(bytes, "glint.exr");
    const Scene scene = build_scene(small_scene());
    Film film(64, 36);
    render(*scene.world, scene.view, film);
    EXPECT_EQ(served.rgb, film.to_image().rgb);

    const auto generation = server_->session().state().generation;
    const auto before = server_->session().latest_frame();
    // A display change shows the same frame again at once, through the new curve: the same samples, the
    // same generation (nothing re-rendered, the scene untouched), another PNG.
    const auto set = post("/api/display", R"({"exposure": 2, "tonemap": "agx"})");
    ASSERT_TRUE(set);
    ASSERT_EQ(set->status, 200) << set->body;
    EXPECT_EQ(json::parse(set->body)["tonemap"], "agx");
    const auto after = server_->session().latest_frame();
    EXPECT_GT(after->id, before->id);
    EXPECT_EQ(after->samples, before->samples);
    EXPECT_EQ(after->generation, generation);
    EXPECT_EQ(server_->session().state().generation, generation);
    EXPECT_NE(after->png, before->png);
    EXPECT_EQ(after->png, encode_png(to_display(film.to_image(), {2, ToneCurve::Agx}), kPngFrameEncoding));
    EXPECT_EQ(server_->session().state().yaml.find("agx"), std::string::npos);  // not in the scene
    // {} goes back to the scene's own display: the first PNG again.
    ASSERT_EQ(post("/api/display", "{}")->status, 200);
    EXPECT_EQ(server_->session().latest_frame()->png, before->png);

    for (const char* bad :
         {R"({"exposure": 100, "tonemap": "agx"})", R"({"exposure": 1, "tonemap": "filmic"})",
          R"({"exposure": 1})", R"([1, 2])", R"({"exposure": "1", "tonemap": "agx"})"}) {
        const auto refused = post("/api/display", bad);
        ASSERT_TRUE(refused);
        EXPECT_EQ(refused->status, 400) << bad;
    }
}

}  // namespace
}  // namespace glint

namespace glint {
namespace {

TEST_F(PreviewServerTest, RefineTakesOnlyABooleanAndSaysWhetherThePatternCanGoOn) {
    const auto on = post("/api/refine", R"({"continuous": true})");
    ASSERT_TRUE(on);
    ASSERT_EQ(on->status, 200) << on->body;
    EXPECT_EQ(json::parse(on->body)["continuous"], true);
    // The default scene samples with the paper's jittered pattern, whose points depend on the count.
    EXPECT_EQ(json::parse(on->body)["extendable"], false);
    EXPECT_EQ(json::parse(client().Get("/api/scene")->body)["continuous"], true);
    ASSERT_EQ(post("/api/refine", R"({"continuous": false})")->status, 200);
    for (const char* bad :
         {R"({"continuous": 1})", R"({})", R"({"continuous": true, "more": 1})", "[true]"}) {
        const auto refused = post("/api/refine", bad);
        ASSERT_TRUE(refused);
        EXPECT_EQ(refused->status, 400) << bad;
    }
}

}  // namespace
}  // namespace glint
