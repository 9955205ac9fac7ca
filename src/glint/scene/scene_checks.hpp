// What a scene that builds may still get wrong without a word: no light at all, or mirrors and glass
// under an integrator that cannot follow them. Each finding is a sentence naming the cause and the fix,
// which `glint render` prints as a warning before it renders (issue 15: no silent black images).
#pragma once

#include <string>
#include <vector>

#include "glint/image/image.hpp"
#include "glint/scene/scene.hpp"

namespace glint {

std::vector<std::string> scene_warnings(const Scene& scene);

// Whether every pixel of a rendered image is exactly black (the warning after a render).
bool all_black(const Image& image);

}  // namespace glint
