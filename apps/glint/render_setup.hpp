// What `glint render` does before and after the render loop, shared by the one-process render
// (main.cpp), its parts (--tile, tile_parts.hpp) and the MPI render (mpi_render.cpp): the options, the
// scene loaded and edited by the flags, the output path, the progress bar, a window of the film.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "glint/image/film.hpp"
#include "glint/image/image.hpp"
#include "glint/import/importer.hpp"
#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_set.hpp"

namespace glint::cli {

inline constexpr int kExitBadInput = 2;

struct RenderOptions {
    std::string scene_path;
    std::string output;
    RenderFlags flags;
    std::optional<int> threads;       // not a scene key: it does not change the image
    std::vector<std::string> sets;    // --set key.path=value, in order
    std::optional<std::string> tile;  // --tile I/N: render part I of N (tile_parts.hpp)
    bool quiet = false;
    ImportOptions import;    // for scenes of other tools (glint/import)
    double time_limit = 0;   // seconds; 0: none
    std::string aov;         // --aov albedo,normal,…: extra layers (glint/render/aov.hpp); empty: none
    std::string checkpoint;  // --checkpoint FILE: the film written there now and then
    double checkpoint_every = 60;  // --checkpoint-every SECONDS
    std::string resume;            // --resume FILE: start from that checkpoint
};

// The output path: -o, or <scene stem>.png, or default.png for the built-in scene.
std::filesystem::path render_output_path(const RenderOptions& options);

// The scene of `options` loaded, edited by the flags and the --set edits in order, and built, with
// --threads applied. `scene_hash` identifies what was built: a hash of glint's version and of the
// scene's tree as YAML after the edits (so two parts or two ranks of different scenes, seeds or sample
// counts differ), not of the files the scene names (meshes, textures). It is computed only when
// `with_scene_hash` (otherwise 0): writing the tree out takes 8.8 M instructions on RTIOW's final scene,
// 11 % of its start-up, which a plain render does not need. The importers' and the scene's warnings are
// printed when `print_warnings`. Throws SceneError.
struct PreparedRender {
    Scene scene;
    std::uint64_t scene_hash = 0;
    std::string camera_yaml;  // the scene's camera block as built from (written into EXR metadata)
};
PreparedRender prepare_render(const RenderOptions& options, bool print_warnings, bool with_scene_hash);

// Whether a one-process render needs the scene hash: to resume from a checkpoint, to write one, or to
// write a tile part. (An MPI render always does: its ranks compare theirs.)
bool needs_scene_hash(const RenderOptions& options);

// The pixels of `window` of a film, as Film::to_image gives them, without converting the rest.
Image film_window(const Film& film, const PixelWindow& window);

// The warning for samples left out as NaN or infinite; nothing when there were none.
void print_nonfinite_warning(const RenderStats& stats);

// The summary's rays, in millions, and what they were: "16.50 M rays (2.56 M camera, 6.99 M bounces,
// 6.95 M shadow)". What next-event estimation costs is the shadow rays; bench/peers.py weighs
// bench/accel's kernel rates by this mix.
std::string rays_summary(const RayCounters& rays);

// A progress bar on stderr: percentage, elapsed time and an estimate of the time left.
class ProgressBar {
  public:
    explicit ProgressBar(bool enabled);
    void update(double fraction);
    void finish();

  private:
    bool enabled_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace glint::cli
