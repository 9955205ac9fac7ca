// Building a SceneDesc tree by hand, for the importers: nodes that carry the position in the imported
// file they come from, and numbers written so that they read back as the same double (the writer
// keeps a scalar's text, so `glint convert` preserves every bit).
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "glint/core/bounds.hpp"
#include "glint/core/color.hpp"
#include "glint/core/vec.hpp"
#include "glint/params/node.hpp"

namespace glint::scene_tree {

// The shortest text that reads back as exactly `value` (std::to_chars).
std::string number_text(double value);

Node text(const std::string& value, const SourcePos& pos);
Node number(double value, const SourcePos& pos);
Node boolean(bool value, const SourcePos& pos);
Node numbers(const std::vector<double>& values, const SourcePos& pos);
Node vec3(const Vec3& value, const SourcePos& pos);
Node color(const Rgb& value, const SourcePos& pos);
Node list(std::vector<Node> items, const SourcePos& pos);
Node map(std::vector<std::pair<std::string, Node>> entries, const SourcePos& pos);

// Adds (or replaces) `key` in a map node.
void set(Node& map, const std::string& key, Node value);

// The position of a whole file, for nodes no single statement stands for (a default camera).
SourcePos file_position(const std::string& path);

// What an importer supplies when the file does not say it (each with a warning by the importer):
// a pinhole camera of 40° vertical field of view looking from +z at the bounding sphere of `bounds`
// (the unit sphere when `bounds` is empty), and a white sky, an environment of radiance 1.
Node framing_camera(const Bounds3& bounds, const SourcePos& pos);
Node white_sky(const SourcePos& pos);

// `file` written relative to `folder` (both made absolute first); absolute when no relative path exists.
std::string path_relative_to(const std::filesystem::path& file, const std::filesystem::path& folder);

}  // namespace glint::scene_tree
