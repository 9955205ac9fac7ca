// The state behind `glint serve`: the scene description being edited, the scene built from it, and a
// render thread that refines it pass after pass and publishes each frame for the browsers watching.
//
// An edit rebuilds only what it touches (commit()). Any change restarts the accumulation at once: the render
// thread abandons its pass at the next tile, shows a coarse preview (one sample per block of pixels) of the
// new view, then refines it.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "glint/image/image.hpp"
#include "glint/image/tone_map.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/serve/scene_edit.hpp"

namespace glint {

class ProgressiveRender;

// One picture sent to the browsers.
struct PreviewFrame {
    std::uint64_t id = 0;          // increases with every frame
    std::uint64_t generation = 0;  // the version of the scene it shows
    int width = 0, height = 0;
    std::uint32_t samples = 0;  // samples per pixel so far (0: the coarse preview)
    std::uint32_t target = 0;   // samples per pixel when complete
    double mrays_per_second = 0;
    double seconds = 0;                   // since the change that started this accumulation
    std::uint64_t nonfinite_samples = 0;  // NaN or infinite samples so far, left out of the picture
    DisplayTransform display;             // how `png` was made from `linear`
    std::shared_ptr<const Image> linear;  // the film's radiance as it is (Save EXR)
    std::vector<unsigned char> png;
    std::string event;  // the whole server-sent event ("event: frame\ndata: {…}\n\n"), made once for all
};

// A render failure (or anything else the page should show) for the current generation.
struct PreviewStatus {
    std::uint64_t generation = 0;
    std::string error;  // empty: rendering fine
};

class PreviewSession {
  public:
    // Builds the scene and starts the render thread. Throws SceneError, also for a value past the
    // preview's limits (serve_limits.hpp), at that value's position.
    PreviewSession(const SceneDesc& desc, std::string display_name);
    ~PreviewSession();
    PreviewSession(const PreviewSession&) = delete;
    PreviewSession& operator=(const PreviewSession&) = delete;

    // Applies the edits to a copy of the description (apply_checked_edits: no file the loaded scene
    // does not refer to, no value past the limits), writes it as YAML, parses and builds that (so any
    // error points at a line of the YAML), and on success makes it current and restarts the render.
    // Throws EditError (or a subclass) or SceneError and leaves everything as it was.
    std::uint64_t apply(const std::vector<SceneEdit>& edits);
    // The same from a request body (apply_edit_request).
    std::uint64_t apply_request(std::string_view request_body);

    struct State {
        std::uint64_t generation;
        Node root;
        std::string yaml;
        RenderSettings settings;  // as built: the defaults filled in
        bool extendable;          // its sample pattern can refine past its target (Sampler::extendable)
    };
    State state() const;
    // The current scene as YAML for a file saved anywhere: its relative file paths made absolute
    // (Export scene).
    std::string export_yaml() const;
    // The built world being rendered: the same object after an edit that kept it (tests use this).
    std::shared_ptr<const World> world() const;
    const std::string& display_name() const { return display_name_; }

    std::shared_ptr<const PreviewFrame> latest_frame() const;
    // Waits until there is a frame other than `seen_id`, the timeout passes or the session stops; then
    // returns the latest frame (possibly still `seen_id`, or null if none yet).
    std::shared_ptr<const PreviewFrame> wait_for_frame(std::uint64_t seen_id,
                                                       std::chrono::milliseconds timeout) const;
    PreviewStatus status() const;

    // Display-only exposure and tone curve: every frame from now on is shown through `display` instead
    // of the scene's render.exposure and render.tonemap, and the latest frame is shown again through it
    // at once. The render goes on undisturbed (nothing is re-rendered), and the scene is not changed: an
    // exported scene keeps its own values. nullopt goes back to the scene's.
    void set_display(std::optional<DisplayTransform> display);
    // What frames are shown through now: the override, or the current scene's own.
    DisplayTransform display() const;

    // Continuous refinement: when on, a finished render goes on, its target doubled each time it is
    // reached, up to preview_limits::kMaxSamples, as long as the scene's sample pattern allows it
    // (Sampler::extendable: sobol, the default, and random); the image after n samples is the bits of a
    // render of n. Off: the render stops at the target it has reached. A scene edit keeps the choice.
    void set_continuous(bool continuous);
    bool continuous() const { return continuous_.load(); }

    // Where the ray through film point (x, y) (pixels, from the top-left) first hits the scene, through
    // the lens centre: the distance along the ray and the depth along the view axis (the distance of
    // the plane of focus that makes that point sharp). nullopt when the ray escapes.
    struct FocusHit {
        double distance, depth;
    };
    std::optional<FocusHit> focus_at(double x, double y) const;

    // Ends the render thread and wakes every waiter; idempotent.
    void stop();
    bool stopping() const { return stop_.load(); }

  private:
    void render_loop();
    bool keeps_refining(const ProgressiveRender& progressive) const;
    // `linear` is the film's radiance; the frame shows it through display().
    void publish(std::shared_ptr<const Image> linear, std::uint64_t generation, std::uint32_t samples,
                 std::uint32_t target, const RenderStats& stats, double seconds);
    void publish_locked(std::shared_ptr<const Image> linear, std::uint64_t generation, std::uint32_t samples,
                        std::uint32_t target, const RenderStats& stats,
                        double seconds);  // publish_mutex_ held

    std::uint64_t commit(EditedScene edited);

    std::string display_name_;
    std::filesystem::path base_dir_;
    std::set<std::string> loaded_files_;  // the files the loaded scene refers to: all an edit may use

    mutable std::mutex mutex_;  // guards everything below that is not atomic
    mutable std::condition_variable changed_;
    Node root_;
    std::string yaml_;
    std::shared_ptr<const Scene> scene_;
    WorldCache world_cache_;  // used with edit_mutex_ held (and by the constructor)
    std::shared_ptr<const PreviewFrame> frame_;
    std::optional<DisplayTransform> display_override_;
    RenderStats frame_stats_;  // the latest frame's, to show it again through another display
    PreviewStatus status_;
    std::uint64_t next_frame_id_ = 1;
    std::atomic<std::uint64_t> generation_{1};
    std::atomic<bool> stop_{false};
    std::atomic<bool> continuous_{false};

    // One publish at a time, from reading the display to storing the frame: a display change then
    // never loses to a frame encoded through the display before it.
    std::mutex publish_mutex_;
    std::mutex edit_mutex_;  // one edit at a time builds a scene
    std::thread render_thread_;
};

}  // namespace glint
