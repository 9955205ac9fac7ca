// Command-line changes of a scene: `--set key.path=value` (Mitsuba's -D, pbrt's overrides), applied to
// the scene's tree before it is built, so every key of the file can be set, and a set value is checked
// by the same builders, with the same messages, as the file's. A misspelt key gets the file's
// did-you-mean, pointing at the argument:
//   --set:1:8: error: unknown key 'samplse' in render; did you mean 'samples'?
//       render.samplse=4
//              ^
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"

namespace glint {

// Applies one `key.path=value` to `desc`. Keys are separated by dots; a number picks an element of a
// list (`objects.0.radius=2`). Missing maps along the path are made; `render.integrator`,
// `render.sampler` and `render.filter` given as a plain word become {type: word} when a key is set below
// them. The value is YAML (`4`, `thin-lens`, `[0, 1, 5]`, `{type: path, max_depth: 8}`). Throws SceneError,
// positioned in the argument, for a malformed assignment or a path through something that is not a map or
// list. `source` names the argument in messages (a flag such as --width is a short form of a --set).
void apply_set(SceneDesc& desc, const std::string& assignment, const std::string& source = "--set");

// The command line's render flags. Each one given is a short form of a --set (flag_edits), so that the
// file, --set and the flags meet the same checks and there is one settings struct, RenderSettings.
struct RenderFlags {
    std::optional<int> width, height, max_depth;
    std::optional<std::uint32_t> samples_per_pixel;
    std::optional<std::int64_t> seed;  // signed, so that --seed -1 is refused by the builder, not wrapped
    std::optional<std::string> sampler, integrator, accelerator;
    std::optional<double> exposure;
    std::optional<std::string> tonemap;
    std::optional<std::string> crop;  // "x0,y0,x1,y1"
};

// The flags given, as (flag, key.path=value). --max-depth sets the integrator's own max_depth when the
// scene gives one (it wins over render.max_depth), else render.max_depth.
std::vector<std::pair<std::string, std::string>> flag_edits(const RenderFlags& flags, const SceneDesc& desc);

// apply_set of each of flag_edits.
void apply_flags(SceneDesc& desc, const RenderFlags& flags);

// The flags applied to `desc`, then each of `sets` (apply_set, in order).
void apply_flags_and_sets(SceneDesc& desc, const RenderFlags& flags, std::span<const std::string> sets);

// The scene with the flags applied, then each of `sets` (apply_set, in order): what `glint render --width …
// --set … FILE` renders, and what the Python module's render() builds from its keywords.
Scene build_scene(SceneDesc desc, const RenderFlags& flags, std::span<const std::string> sets = {});

}  // namespace glint
