// SceneDesc → YAML text: the inverse of the loader, so that a scene edited in memory (by `glint serve`)
// can be saved and rendered again by `glint render`. Comments and positions of the original file are
// not kept; everything the builders read is: parse(write(tree)) is the same tree.
#pragma once

#include <string>

#include "glint/params/node.hpp"

namespace glint {

// The YAML text of a scene's top-level map (or of any node). Small maps and lists of plain values are
// written on one line ({type: sphere, radius: 1}, [0, 1, 0]), the rest as indented blocks. Scalars are
// written as they were read, quoted only when YAML would otherwise read something else.
std::string write_scene_yaml(const Node& root);

// Whether two trees hold the same values (kinds, keys in order, scalar texts); positions are ignored.
bool same_tree(const Node& a, const Node& b);

}  // namespace glint
