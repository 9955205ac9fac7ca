// The scene `glint render` draws without a file: the paper's subject in one picture — spheres on a
// floor, lit by two point lights with hard shadows and a little ambient light.
#include "glint/scene/scene_desc.hpp"

namespace glint {

const std::string& default_scene_text() {
    static const std::string text = R"(# glint's built-in default scene
render:
  width: 640
  height: 360
  samples: 16
  sampler: jittered
  seed: 1

camera:
  type: pinhole
  eye: [0, 1.6, 7]
  look_at: [0, 0.8, 0]
  up: [0, 1, 0]
  fov: 35

background: [0.55, 0.7, 0.9]

materials:
  floor: {type: matte, albedo: 0.6}
  red:   {type: matte, albedo: [0.8, 0.15, 0.1]}
  green: {type: matte, albedo: [0.2, 0.7, 0.25]}
  blue:  {type: matte, albedo: [0.15, 0.3, 0.8]}

objects:
  - {type: plane,  point: [0, 0, 0], normal: [0, 1, 0], material: floor}
  - {type: sphere, center: [0, 1, 0], radius: 1, material: red}
  - {type: sphere, center: [-2.2, 0.7, 0.6], radius: 0.7, material: green}
  - {type: sphere, center: [2.1, 0.6, 0.9], radius: 0.6, material: blue}

lights:
  - {type: ambient, radiance: 0.12}
  - {type: point, position: [4, 6, 5], intensity: 90}
  - {type: point, position: [-5, 4, 3], intensity: 25}
)";
    return text;
}

SceneDesc default_scene() {
    return parse_scene_text(default_scene_text(), "<default scene>", ".");
}

}  // namespace glint
