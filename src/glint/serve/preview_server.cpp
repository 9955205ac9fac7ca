#include "glint/serve/preview_server.hpp"

#include <httplib.h>
#include <sys/socket.h>

#include <nlohmann/json.hpp>

#include "glint/camera/camera.hpp"
#include "glint/integrator/integrator.hpp"
#include "glint/material/material.hpp"
#include "glint/sampling/sampler.hpp"
#include "glint/serve/preview_session.hpp"
#include "glint/serve/web_assets.hpp"

namespace glint {

namespace {

constexpr size_t kMaxRequestBody = 64 * 1024;
// An idle stream writes a comment this often, which is also how a closed browser tab is noticed.
constexpr auto kKeepAliveComment = std::chrono::seconds(2);

void send_json(httplib::Response& res, const nlohmann::ordered_json& body, int status = 200) {
    res.status = status;
    res.set_header("Cache-Control", "no-store");
    res.set_content(body.dump(), "application/json");
}

void send_error(httplib::Response& res, int status, const std::string& message) {
    send_json(res, {{"error", message}}, status);
}

// Parses a JSON request body; on failure answers 4xx and returns nullopt.
std::optional<nlohmann::json> json_body(const httplib::Request& req, httplib::Response& res) {
    const std::string type = req.get_header_value("Content-Type");
    if (type.rfind("application/json", 0) != 0) {
        // Also what keeps other web sites out: a cross-origin JSON POST needs a preflight we refuse.
        send_error(res, 415, "send the request as Content-Type: application/json");
        return std::nullopt;
    }
    nlohmann::json body = nlohmann::json::parse(req.body, nullptr, false);
    if (body.is_discarded()) {
        send_error(res, 400, "the request body is not valid JSON");
        return std::nullopt;
    }
    return body;
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
    httplib::Server http;
    std::string host;
    int port = 0;
    std::atomic<int> open_streams{0};
    std::atomic<bool> stopping{false};
    int listen_socket = -1;

    Impl(const SceneDesc& desc, const std::string& name) : session(desc, name) {}

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
                {"scene", node_to_json(state.root)},
                {"yaml", state.yaml},
                {"render_error", status.generation == state.generation ? status.error : ""},
                {"samplers", described(sampler_table())},
                {"integrators", described(integrator_table())},
                {"cameras", names_of(camera_table())},
                {"material_types", names_of(material_table())},
                {"max_pixels", PreviewSession::kMaxPixels}};
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
        http.new_task_queue = [] { return new httplib::ThreadPool(kThreads); };
        // Keep httplib's own socket options (address reuse) and remember the socket, see bind().
        http.set_socket_options([this](int socket) {
            int yes = 1;
            ::setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof(yes));
            listen_socket = socket;
        });
        http.set_payload_max_length(kMaxRequestBody);
        http.set_keep_alive_timeout(2);
        http.set_read_timeout(5);
        http.set_write_timeout(5);

        http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
            if (!host_allowed(req)) {
                res.status = 403;
                res.set_content("glint serve answers to 127.0.0.1 and localhost only\n", "text/plain");
                return httplib::Server::HandlerResponse::Handled;
            }
            res.set_header("X-Content-Type-Options", "nosniff");
            return httplib::Server::HandlerResponse::Unhandled;
        });
        http.set_exception_handler(
            [](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
                std::string message = "internal error";
                try {
                    std::rethrow_exception(ep);
                } catch (const std::exception& e) {
                    message += std::string(": ") + e.what();
                } catch (...) {
                }
                send_error(res, 500, message);
            });
        // Every error answer has a body that says what went wrong.
        http.set_error_handler([](const httplib::Request&, httplib::Response& res) {
            if (res.body.empty()) {
                const char* what = res.status == 404   ? "not found"
                                   : res.status == 413 ? "the request is too large"
                                   : res.status == 400 ? "malformed request"
                                                       : "request refused";
                res.set_content(std::string(what) + "\n", "text/plain");
            }
        });

        http.Get("/api/scene",
                 [this](const httplib::Request&, httplib::Response& res) { send_json(res, state_json()); });

        http.Post("/api/edit", [this](const httplib::Request& req, httplib::Response& res) {
            const auto body = json_body(req, res);
            if (!body) {
                return;
            }
            try {
                session.apply(parse_edits(*body));
                send_json(res, state_json());
            } catch (const EditError& e) {
                send_error(res, 400, e.what());
            } catch (const SceneError& e) {
                send_error(res, 422, e.what());
            }
        });

        http.Post("/api/focus", [this](const httplib::Request& req, httplib::Response& res) {
            const auto body = json_body(req, res);
            if (!body) {
                return;
            }
            if (!body->is_object() || !(*body)["x"].is_number() || !(*body)["y"].is_number()) {
                send_error(res, 400, "expected {\"x\": pixels, \"y\": pixels}");
                return;
            }
            const auto hit = session.focus_at((*body)["x"].get<double>(), (*body)["y"].get<double>());
            if (!hit) {
                send_json(res, {{"hit", false}});
                return;
            }
            send_json(res, {{"hit", true}, {"distance", hit->distance}, {"depth", hit->depth}});
        });

        http.Get("/api/image.png", [this](const httplib::Request&, httplib::Response& res) {
            const auto frame = session.latest_frame();
            if (!frame) {
                send_error(res, 503, "no image yet");
                return;
            }
            res.set_header("Cache-Control", "no-store");
            res.set_header("Content-Disposition", "attachment; filename=\"glint.png\"");
            res.set_content(reinterpret_cast<const char*>(frame->png.data()), frame->png.size(), "image/png");
        });

        http.Get("/api/scene.yaml", [this](const httplib::Request&, httplib::Response& res) {
            res.set_header("Cache-Control", "no-store");
            res.set_header("Content-Disposition", "attachment; filename=\"scene.yaml\"");
            res.set_content("# Exported by glint serve: glint render scene.yaml renders this view.\n" +
                                session.state().yaml,
                            "application/yaml");
        });

        http.Get("/api/events", [this](const httplib::Request&, httplib::Response& res) {
            if (open_streams.fetch_add(1) >= kMaxEventStreams) {
                open_streams.fetch_sub(1);
                send_error(res, 503, "too many open event streams");
                return;
            }
            res.set_header("Cache-Control", "no-store");
            auto seen = std::make_shared<std::uint64_t>(0);
            res.set_chunked_content_provider(
                "text/event-stream",
                [this, seen](size_t, httplib::DataSink& sink) {
                    if (stopping || session.stopping()) {
                        sink.done();
                        return true;
                    }
                    const auto frame = session.wait_for_frame(*seen, kKeepAliveComment);
                    if (stopping || session.stopping()) {
                        sink.done();
                        return true;
                    }
                    if (!frame || frame->id == *seen) {
                        static constexpr char ping[] =
                            ": still here\n\n";  // keeps proxies and the browser content
                        return sink.write(ping, sizeof(ping) - 1);
                    }
                    *seen = frame->id;
                    return sink.write(frame->event.data(), frame->event.size());
                },
                [this](bool) { open_streams.fetch_sub(1); });
        });

        // The page itself: exactly the embedded files, nothing from the disk.
        http.Get(R"(/[^?]*)", [](const httplib::Request& req, httplib::Response& res) {
            const WebAsset* asset = find_web_asset(req.path);
            if (!asset) {
                res.status = 404;
                res.set_content("not found\n", "text/plain");
                return;
            }
            res.set_header("Cache-Control", "no-cache");
            res.set_content(asset->bytes.data(), asset->bytes.size(),
                            std::string(asset->content_type).c_str());
        });
    }
};

PreviewServer::PreviewServer(const SceneDesc& desc, const std::string& display_name)
    : impl_(std::make_unique<Impl>(desc, display_name)) {
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
