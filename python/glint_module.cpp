// glint as a Python module (pybind11): glint.render(scene, spp=…, …) returns the film as a numpy array, and a
// mistake in the scene raises glint.SceneError with its file, line and column. It calls the library as
// `glint render` does (load_scene / parse_scene_text, then build_scene with the flags and the --set edits),
// so a Python render is bit for bit the command's PFM. README.md and docs/library.md describe it.
#include <Python.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <variant>
#include <vector>

#include "glint/import/importer.hpp"
#include "glint/params/diagnostics.hpp"
#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_checks.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"

namespace py = pybind11;

namespace {

// The exception and warning classes, made once at import and owned by the module (never freed: a
// translator may run until the interpreter ends).
PyObject* g_scene_error = nullptr;
PyObject* g_scene_warning = nullptr;

constexpr const char* kSceneTextName = "<scene text>";

// What render() was given: nothing (the built-in default scene), a file, or the scene's text.
struct SceneSource {
    std::optional<std::filesystem::path> path;
    std::optional<std::string> text;
};

// A str naming an existing file is that file; any other str holding a newline, a ':' or a '{' is the scene
// itself (YAML or JSON); any other str, and any os.PathLike, is a path (a missing file is a SceneError).
SceneSource scene_source(const py::object& scene) {
    if (scene.is_none()) {
        return {};
    }
    if (py::isinstance<py::str>(scene)) {
        std::string text = scene.cast<std::string>();
        std::error_code ec;
        const bool is_file =
            text.find('\n') == std::string::npos && std::filesystem::is_regular_file(text, ec);
        if (!is_file && text.find_first_of("\n:{") != std::string::npos) {
            return {std::nullopt, std::move(text)};
        }
        return {std::filesystem::path(text), std::nullopt};
    }
    const py::object fspath = py::module_::import("os").attr("fspath");
    return {std::filesystem::path(fspath(scene).cast<std::string>()), std::nullopt};
}

glint::SceneDesc load(const SceneSource& source) {
    if (source.text) {
        // Relative paths in the text (meshes, images) resolve against the working directory.
        return glint::parse_scene_text(*source.text, kSceneTextName, std::filesystem::current_path());
    }
    return source.path ? glint::load_scene(*source.path) : glint::default_scene();
}

void warn(const std::string& message) {
    if (PyErr_WarnEx(g_scene_warning, message.c_str(), 2) != 0) {
        throw py::error_already_set();  // warnings turned into errors
    }
}

// Renders on a thread of its own while this one, without the GIL, looks for Ctrl-C every 50 ms: Python
// runs its signal handlers on the main thread only, so this is how KeyboardInterrupt (a notebook's
// "interrupt kernel") stops a long render. Returns false when interrupted, with the Python error set.
bool render_interruptibly(const glint::Scene& scene, glint::Film& film, glint::RenderStats& stats) {
    std::atomic<bool> cancel{false};
    bool interrupted = false;
    std::exception_ptr failure;
    {
        py::gil_scoped_release release;
        std::mutex mutex;
        std::condition_variable finished_signal;
        bool finished = false;
        std::thread worker([&] {
            glint::RenderCallbacks callbacks;
            callbacks.cancel = &cancel;
            try {
                stats = glint::render(scene, film, callbacks);
            } catch (...) {
                failure = std::current_exception();
            }
            const std::lock_guard lock(mutex);
            finished = true;
            finished_signal.notify_one();
        });
        std::unique_lock lock(mutex);
        while (!finished_signal.wait_for(lock, std::chrono::milliseconds(50), [&] { return finished; })) {
            if (interrupted) {
                continue;  // cancelled: wait for the render to stop at its next tile
            }
            lock.unlock();
            {
                const py::gil_scoped_acquire gil;
                interrupted = PyErr_CheckSignals() != 0;
            }
            cancel.store(interrupted);
            lock.lock();
        }
        lock.unlock();
        worker.join();
    }
    if (failure) {
        std::rethrow_exception(failure);
    }
    return !interrupted;
}

// The film's image as a (height, width, 3) float32 array that owns the pixels (no copy).
py::array_t<float> to_array(glint::Image image) {
    auto* pixels = new std::vector<float>(std::move(image.rgb));
    const py::capsule owner(pixels, [](void* p) { delete static_cast<std::vector<float>*>(p); });
    const auto height = static_cast<py::ssize_t>(image.height);
    const auto width = static_cast<py::ssize_t>(image.width);
    return py::array_t<float>({height, width, py::ssize_t{3}}, pixels->data(), owner);
}

py::array_t<float> render(const py::object& scene, std::optional<std::uint32_t> spp, std::optional<int> width,
                          std::optional<int> height, std::optional<std::int64_t> seed,
                          std::optional<int> threads, std::optional<std::string> integrator,
                          std::optional<std::string> sampler, std::optional<int> max_depth,
                          std::optional<std::string> accel, const std::vector<std::string>& sets) {
    if (threads && *threads < 0) {
        throw py::value_error("threads must be 0 (all cores) or more, not " + std::to_string(*threads));
    }
    glint::RenderFlags flags;
    flags.samples_per_pixel = spp;
    flags.width = width;
    flags.height = height;
    flags.seed = seed;
    flags.integrator = std::move(integrator);
    flags.sampler = std::move(sampler);
    flags.max_depth = max_depth;
    flags.accelerator = std::move(accel);

    const SceneSource source = scene_source(scene);
    glint::SceneDesc desc;
    {
        const py::gil_scoped_release release;  // reading a large mesh takes a while
        desc = load(source);
    }
    for (const glint::SceneWarning& warning : desc.warnings) {
        warn(warning.to_string());
    }
    glint::Scene built;
    {
        const py::gil_scoped_release release;  // building a BVH too
        built = glint::build_scene(std::move(desc), flags, sets);
    }
    for (const std::string& warning : glint::scene_warnings(built)) {
        warn(warning);
    }
    if (threads) {
        built.view.settings.threads = *threads;
    }

    glint::Film film(built.view.settings.width, built.view.settings.height);
    glint::RenderStats stats;
    if (!render_interruptibly(built, film, stats)) {
        throw py::error_already_set();
    }
    if (stats.nonfinite_samples > 0) {
        warn(std::to_string(stats.nonfinite_samples) +
             " samples were NaN or infinite and were left out of the image (first at pixel (" +
             std::to_string(stats.first_nonfinite_x) + ", " + std::to_string(stats.first_nonfinite_y) +
             "), sample " + std::to_string(stats.first_nonfinite_sample) + ")");
    }
    py::array_t<float> image = to_array(film.to_image());
    if (const auto& crop = built.view.settings.crop) {  // only the window was rendered: return it alone
        const py::object window =
            image[py::make_tuple(py::slice(crop->y0, crop->y1, 1), py::slice(crop->x0, crop->x1, 1))];
        return window.attr("copy")();
    }
    return image;
}

// glint::SceneError → glint.SceneError(what()), with file, line, column (None when unknown) and message.
void translate_scene_error(std::exception_ptr error) {
    try {
        if (error) {
            std::rethrow_exception(error);
        }
    } catch (const glint::SceneError& e) {
        const glint::SourcePos& pos = e.position();
        const py::object exception = py::reinterpret_borrow<py::object>(g_scene_error)(e.what());
        exception.attr("file") = pos.file ? py::cast(pos.file->path) : py::none();
        exception.attr("line") = pos.line > 0 ? py::cast(pos.line) : py::none();
        exception.attr("column") = pos.column > 0 ? py::cast(pos.column) : py::none();
        exception.attr("message") = e.message();
        PyErr_SetObject(g_scene_error, exception.ptr());
    }
}

}  // namespace

PYBIND11_MODULE(glint, module) {
    module.doc() =
        "glint, a ray tracer: render a scene file or scene text into a numpy array of linear radiance";
    module.attr("__version__") = GLINT_VERSION;

    g_scene_error = PyErr_NewExceptionWithDoc(
        "glint.SceneError",
        "A mistake in a scene: str() is the whole report (file:line:col: error: ..., the line and a caret); "
        "file, line and column say where (None when unknown), message what.",
        PyExc_ValueError, nullptr);
    g_scene_warning = PyErr_NewExceptionWithDoc(
        "glint.SceneWarning",
        "Something in a scene that glint reads but does not render as its author meant.", PyExc_UserWarning,
        nullptr);
    if (g_scene_error == nullptr || g_scene_warning == nullptr) {
        throw py::error_already_set();
    }
    module.attr("SceneError") = py::reinterpret_borrow<py::object>(g_scene_error);
    module.attr("SceneWarning") = py::reinterpret_borrow<py::object>(g_scene_warning);
    py::register_exception_translator(translate_scene_error);

    module.def("render", &render, py::arg("scene") = py::none(), py::kw_only(), py::arg("spp") = py::none(),
               py::arg("width") = py::none(), py::arg("height") = py::none(), py::arg("seed") = py::none(),
               py::arg("threads") = py::none(), py::arg("integrator") = py::none(),
               py::arg("sampler") = py::none(), py::arg("max_depth") = py::none(),
               py::arg("accel") = py::none(), py::arg("sets") = std::vector<std::string>{},
               R"(Renders a scene and returns its film: a float32 array (height, width, 3) of linear radiance,
exactly what `glint render -o image.pfm` writes (top row first).

scene: a path (str or os.PathLike) to a glint YAML/JSON, pbrt-v4, glTF or OBJ scene; or the scene's YAML or
    JSON text (a str with a newline, ':' or '{' that names no file); None: the built-in default scene.
spp, width, height, seed, integrator, sampler, max_depth, accel: as the flags of `glint render`.
threads: worker threads, 0 or None for all cores; the image is the same bits for any value.
sets: "key.path=value" edits applied after the keywords, in order, as `--set`.

Raises glint.SceneError (a ValueError) for a mistake in the scene or a keyword; warns glint.SceneWarning.
The GIL is released while the scene loads, builds and renders; Ctrl-C stops the render (KeyboardInterrupt).)");
}
