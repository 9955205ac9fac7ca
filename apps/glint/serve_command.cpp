// `glint serve [SCENE] [--port 8080] [--host 127.0.0.1]`: renders the scene progressively and shows it
// in the browser, with controls that edit the scene description.
#include <atomic>
#include <csignal>
#include <iostream>
#include <thread>

#include "commands.hpp"
#include "glint/import/importer.hpp"
#include "glint/serve/preview_server.hpp"

namespace {

constexpr int kExitBadInput = 2;

volatile std::sig_atomic_t g_stop_requested = 0;

extern "C" void request_stop(int) {
    g_stop_requested = 1;
}

struct ServeOptions {
    std::string scene_path;
    std::string host = "127.0.0.1";
    int port = 8080;
};

int run_serve(const ServeOptions& options) {
    std::unique_ptr<glint::PreviewServer> server;
    try {
        const glint::SceneDesc desc =
            options.scene_path.empty() ? glint::default_scene() : glint::load_scene(options.scene_path);
        print_warnings(desc);
        server = std::make_unique<glint::PreviewServer>(
            desc, options.scene_path.empty() ? "default scene" : options.scene_path);
    } catch (const glint::SceneError& e) {
        // Also a scene past the preview's limits (glint::preview_limits), at the offending value.
        std::cerr << e.what() << '\n';
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::cerr << "glint: error: " << e.what() << '\n';
        return 1;
    }
    int port = 0;
    try {
        port = server->bind(options.host, options.port);
    } catch (const std::exception& e) {
        std::cerr << "glint: error: " << e.what() << '\n';
        return 1;
    }
    const bool ipv6 = options.host.find(':') != std::string::npos;
    std::cout << "glint: serving " << (options.scene_path.empty() ? "the default scene" : options.scene_path)
              << " at http://" << (ipv6 ? "[" + options.host + "]" : options.host) << ':' << port
              << "/  (Ctrl-C to stop)" << std::endl;
    if (options.host != "127.0.0.1" && options.host != "localhost" && options.host != "::1") {
        std::cout << "glint: warning: listening beyond this machine; anyone who can reach " << options.host
                  << " can watch and edit the scene" << std::endl;
    }

    std::signal(SIGINT, request_stop);
    std::signal(SIGTERM, request_stop);
    std::atomic<bool> server_ended{false};
    std::thread http([&] {
        try {
            server->run();
        } catch (const std::exception& e) {
            std::cerr << "glint: error: " << e.what() << '\n';
        }
        server_ended = true;  // the server is gone: leave too, instead of waiting for Ctrl-C
    });
    while (!g_stop_requested && !server_ended) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    std::cout << "glint: stopping" << std::endl;
    server->stop();
    http.join();
    return 0;
}

}  // namespace

void add_serve_command(CLI::App& app) {
    auto options = std::make_shared<ServeOptions>();
    CLI::App* serve = app.add_subcommand(
        "serve", "Live preview in the browser: edit the view and settings, watch the image refine");
    serve->add_option("scene", options->scene_path,
                      "Scene file (YAML or JSON); omitted: the built-in default scene");
    serve->add_option("--port", options->port, "TCP port (0: any free port)")->check(CLI::Range(0, 65535));
    serve->add_option("--host", options->host,
                      "Address to listen on (default 127.0.0.1: this machine only; 0.0.0.0 exposes the scene "
                      "to the network)");
    // Runs while app.parse() runs; a failure comes back to main() as CLI::RuntimeError(exit code).
    serve->callback([options] {
        if (const int code = run_serve(*options); code != 0) {
            throw CLI::RuntimeError(code);
        }
    });
}
