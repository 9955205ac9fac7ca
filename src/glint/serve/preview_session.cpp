#include "glint/serve/preview_session.hpp"

#include <cmath>

#include "glint/image/image_io.hpp"
#include "glint/image/tone_map.hpp"
#include "glint/import/importer.hpp"
#include "glint/render/progressive.hpp"
#include "glint/scene/scene_writer.hpp"
#include "glint/serve/serve_limits.hpp"

namespace glint {

namespace {

// The coarse preview takes about this many samples, whatever the image size, so that the first
// picture of a new view comes back quickly.
constexpr double kCoarseSamples = 12000;

// The preview's own limits, checked on the built settings too, so that no reading of a value (a
// conversion, a default) gets past them; the tree was checked already.
void check_preview_limits(const SceneDesc& desc, const RenderSettings& s) {
    const std::int64_t pixels = static_cast<std::int64_t>(s.width) * s.height;
    if (pixels > preview_limits::kMaxPixels || s.width > preview_limits::kMaxSide ||
        s.height > preview_limits::kMaxSide || s.samples_per_pixel > preview_limits::kMaxSamples ||
        s.max_depth > preview_limits::kMaxDepth) {
        const Node* render = desc.root.find("render");
        throw SceneError(render ? render->pos : desc.root.pos,
                         "the preview renders at most " + std::to_string(preview_limits::kMaxSide) +
                             " pixels a side, " + std::to_string(preview_limits::kMaxPixels) + " pixels, " +
                             std::to_string(preview_limits::kMaxSamples) + " samples and depth " +
                             std::to_string(preview_limits::kMaxDepth) + "; use glint render beyond that");
    }
}

}  // namespace

PreviewSession::PreviewSession(const SceneDesc& desc, std::string display_name)
    : display_name_(std::move(display_name)),
      base_dir_(desc.base_dir),
      loaded_files_(file_references(desc.root)) {
    // The user's own file, so its errors point into it.
    if (const auto violation = find_limit_violation(desc.root)) {
        throw SceneError(violation->node ? violation->node->pos : desc.root.pos, violation->message);
    }
    root_ = desc.root;
    yaml_ = write_scene_yaml(root_);
    auto scene = std::make_shared<Scene>(build_scene(desc, &world_cache_));
    check_preview_limits(desc, scene->view.settings);
    scene_ = std::move(scene);
    render_thread_ = std::thread([this] { render_loop(); });
}

PreviewSession::~PreviewSession() {
    stop();
}

void PreviewSession::stop() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    changed_.notify_all();
    if (render_thread_.joinable() && render_thread_.get_id() != std::this_thread::get_id()) {
        render_thread_.join();
    }
}

std::uint64_t PreviewSession::apply(const std::vector<SceneEdit>& edits) {
    std::lock_guard edit_lock(edit_mutex_);
    SceneDesc current;
    {
        std::lock_guard lock(mutex_);
        current.root = root_;
    }
    current.base_dir = base_dir_;
    return commit(apply_checked_edits(current, edits, loaded_files_));
}

std::uint64_t PreviewSession::apply_request(std::string_view request_body) {
    // Parsed before taking the edit lock: a bad body costs no waiting for another edit's build.
    const std::vector<SceneEdit> edits = parse_edits(parse_request_json(request_body));
    return apply(edits);
}

// Called with edit_mutex_ held. Rebuilds only what the edits touched: a change of the camera or the
// render settings keeps the built world (no mesh read, no BVH built); a change of the world reuses every
// shape whose description is unchanged and the accelerator over them (world_cache_); a change that
// changes nothing keeps everything, the accumulation included.
std::uint64_t PreviewSession::commit(EditedScene edited) {
    SceneDesc current;
    std::shared_ptr<const Scene> scene;
    {
        std::lock_guard lock(mutex_);
        current.root = root_;
        scene = scene_;
    }
    current.base_dir = base_dir_;
    if (same_tree(current.root, edited.desc.root)) {
        std::lock_guard lock(mutex_);
        return generation_.load();
    }
    auto rebuilt = std::make_shared<Scene>();
    if (same_world(current, edited.desc)) {
        rebuilt->view = build_view(edited.desc);
        rebuilt->world = scene->world;
    } else {
        *rebuilt = build_scene(edited.desc, &world_cache_);  // checks the top level too
    }
    check_preview_limits(edited.desc, rebuilt->view.settings);
    std::uint64_t generation = 0;
    {
        std::lock_guard lock(mutex_);
        root_ = std::move(edited.desc.root);
        yaml_ = std::move(edited.yaml);
        scene_ = std::move(rebuilt);
        generation = generation_.load() + 1;
        generation_ = generation;  // the render thread's cancel check sees this at its next tile
        status_ = {generation, ""};
    }
    changed_.notify_all();
    return generation;
}

PreviewSession::State PreviewSession::state() const {
    std::lock_guard lock(mutex_);
    return {generation_.load(), root_, yaml_, scene_->view.settings, scene_->view.sampler->extendable()};
}

std::string PreviewSession::export_yaml() const {
    SceneDesc desc;
    {
        std::lock_guard lock(mutex_);
        desc.root = root_;
    }
    desc.base_dir = base_dir_;
    return scene_yaml_with_absolute_paths(desc);
}

std::shared_ptr<const World> PreviewSession::world() const {
    std::lock_guard lock(mutex_);
    return scene_->world;
}

std::shared_ptr<const PreviewFrame> PreviewSession::latest_frame() const {
    std::lock_guard lock(mutex_);
    return frame_;
}

std::shared_ptr<const PreviewFrame> PreviewSession::wait_for_frame(std::uint64_t seen_id,
                                                                   std::chrono::milliseconds timeout) const {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, timeout, [&] { return stop_.load() || (frame_ && frame_->id != seen_id); });
    return frame_;
}

PreviewStatus PreviewSession::status() const {
    std::lock_guard lock(mutex_);
    return status_;
}

std::optional<PreviewSession::FocusHit> PreviewSession::focus_at(double x, double y) const {
    std::shared_ptr<const Scene> scene;
    {
        std::lock_guard lock(mutex_);
        scene = scene_;
    }
    const double w = scene->view.settings.width, h = scene->view.settings.height;
    if (!(x >= 0 && x <= w && y >= 0 && y <= h)) {
        return std::nullopt;
    }
    const Ray ray = scene->view.camera->generate_ray({x, y}, {0.5, 0.5});
    const Ray axis = scene->view.camera->generate_ray({w / 2, h / 2}, {0.5, 0.5});
    Hit hit;
    if (!scene->world->intersect(ray, std::numeric_limits<double>::infinity(), hit)) {
        return std::nullopt;
    }
    const double distance = hit.t * length(ray.direction);
    const double cosine = dot(normalize(ray.direction), normalize(axis.direction));
    return FocusHit{distance, distance * cosine};
}

bool PreviewSession::keeps_refining(const ProgressiveRender& progressive) const {
    return continuous_.load() && progressive.extendable() &&
           progressive.target_samples() < preview_limits::kMaxSamples;
}

void PreviewSession::set_continuous(bool continuous) {
    {
        std::lock_guard lock(mutex_);
        continuous_ = continuous;
    }
    changed_.notify_all();
}

DisplayTransform PreviewSession::display() const {
    std::lock_guard lock(mutex_);
    return display_override_ ? *display_override_ : scene_->view.settings.display;
}

void PreviewSession::set_display(std::optional<DisplayTransform> display) {
    std::lock_guard publishing(publish_mutex_);
    std::shared_ptr<const PreviewFrame> latest;
    RenderStats stats;
    {
        std::lock_guard lock(mutex_);
        display_override_ = display;
        latest = frame_;
        stats = frame_stats_;
    }
    if (latest && latest->linear) {
        publish_locked(latest->linear, latest->generation, latest->samples, latest->target, stats,
                       latest->seconds);
    }
}

void PreviewSession::publish(std::shared_ptr<const Image> linear, std::uint64_t generation,
                             std::uint32_t samples, std::uint32_t target, const RenderStats& stats,
                             double seconds) {
    std::lock_guard publishing(publish_mutex_);
    publish_locked(std::move(linear), generation, samples, target, stats, seconds);
}

void PreviewSession::publish_locked(std::shared_ptr<const Image> linear, std::uint64_t generation,
                                    std::uint32_t samples, std::uint32_t target, const RenderStats& stats,
                                    double seconds) {
    const double mrays = stats.mrays_per_second();
    auto frame = std::make_shared<PreviewFrame>();
    frame->generation = generation;
    frame->width = linear->width;
    frame->height = linear->height;
    frame->display = display();
    const Image image = to_display(*linear, frame->display);
    frame->linear = std::move(linear);
    frame->samples = samples;
    frame->target = target;
    frame->mrays_per_second = mrays;
    frame->seconds = seconds;
    frame->nonfinite_samples = stats.nonfinite_samples;
    frame->png = encode_png(image, kPngFrameEncoding);
    {
        std::lock_guard lock(mutex_);
        if (generation != generation_.load()) {
            return;  // the scene changed while encoding: this picture is already stale
        }
        frame->id = next_frame_id_++;
        nlohmann::json data = {{"id", frame->id},
                               {"generation", generation},
                               {"width", frame->width},
                               {"height", frame->height},
                               {"samples", samples},
                               {"target", target},
                               {"mrays_per_second", std::round(mrays * 100) / 100},
                               {"seconds", std::round(seconds * 1000) / 1000},
                               {"exposure", frame->display.exposure},
                               {"continuous", continuous_.load()},
                               {"tonemap", tone_curve_table().name_of(frame->display.curve)},
                               // The picture itself travels as binary PNG, fetched by the page from this
                               // address (GET /api/frames/ID.png), not as base64 inside the event. Whole:
                               // a PNG of the per-pixel change from the previous frame ((B - A) mod 256)
                               // is, through glint's PNG writer (png.cpp), 74 % of the whole frame on
                               // average for the Cornell box at 512x512 from 1 to 256 spp and 92 % for
                               // examples/lights.yaml at 640x360 (72 % and 92 % with stb_image_write,
                               // which glint used before): too little for a second decoder on the page.
                               // The writer itself is what made frames compact: zlib's run-length deflate
                               // makes them 33 % and 27 % smaller than stb's fixed Huffman codes did, in
                               // a fifth of the time.
                               {"image", "/api/frames/" + std::to_string(frame->id) + ".png"}};
        if (stats.nonfinite_samples > 0) {
            // Left out of the picture, as by glint render, and named so that the page can say where.
            data["nonfinite"] = {{"samples", stats.nonfinite_samples},
                                 {"x", stats.first_nonfinite_x},
                                 {"y", stats.first_nonfinite_y},
                                 {"sample", stats.first_nonfinite_sample}};
        }
        frame->event = "event: frame\ndata: " + data.dump() + "\n\n";
        frame_ = std::move(frame);
        frame_stats_ = stats;
    }
    changed_.notify_all();
}

void PreviewSession::render_loop() {
    std::uint64_t generation = 0;
    std::shared_ptr<const Scene> scene;
    std::unique_ptr<ProgressiveRender> progressive;
    std::chrono::steady_clock::time_point started;
    const auto cancelled = [&] {
        return stop_.load(std::memory_order_relaxed) || generation_.load() != generation;
    };
    while (true) {
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [&] {
                return stop_.load() || generation_.load() != generation ||
                       (progressive && (!progressive->complete() || keeps_refining(*progressive)));
            });
            if (stop_) {
                return;
            }
            if (generation_.load() != generation) {
                generation = generation_.load();
                progressive.reset();  // before the scene it refers to
                scene = scene_;
            }
        }
        try {
            if (!progressive) {
                started = std::chrono::steady_clock::now();
                progressive = std::make_unique<ProgressiveRender>(*scene->world, scene->view);
                const double pixels =
                    static_cast<double>(scene->view.settings.width) * scene->view.settings.height;
                const int block =
                    std::max(1, static_cast<int>(std::lround(std::sqrt(pixels / kCoarseSamples))));
                Image coarse;
                if (block > 1 && progressive->coarse_preview(block, coarse, cancelled)) {
                    publish(
                        std::make_shared<const Image>(std::move(coarse)), generation, 0,
                        progressive->target_samples(), progressive->stats(),
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
                }
                continue;
            }
            if (progressive->complete() && keeps_refining(*progressive)) {
                // Continuous refinement: twice the samples, the same bits as a render of that many.
                progressive->extend_target(static_cast<std::uint32_t>(std::min<std::int64_t>(
                    2 * std::int64_t{progressive->target_samples()}, preview_limits::kMaxSamples)));
            }
            if (progressive->next_pass(cancelled)) {
                publish(std::make_shared<const Image>(progressive->film().to_image()), generation,
                        progressive->samples_done(), progressive->target_samples(), progressive->stats(),
                        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count());
            }
        } catch (const std::exception& e) {
            // Keep serving: show the error and wait for the next change.
            std::lock_guard lock(mutex_);
            status_ = {generation, std::string("render failed: ") + e.what()};
            progressive.reset();  // nothing in progress: the loop waits for the next change
        } catch (...) {
            std::lock_guard lock(mutex_);
            status_ = {generation, "render failed"};
            progressive.reset();
        }
    }
}

}  // namespace glint
