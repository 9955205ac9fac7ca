// glint inside another program: build a scene in code or load a scene file, render it, read the pixels.
//
//   glint_library_example                                the scene of kScene; prints its mean radiance
//   glint_library_example SCENE [OUT.pfm] [KEY=VALUE …]  any scene glint reads, with `--set` edits; writes
//                                                        the film (PFM or EXR: exactly what `glint render
//                                                        -o OUT.pfm --set KEY=VALUE …` writes)
//
// Only the stable API of docs/library.md is used. Exit codes as glint's: 2 for a mistake in the scene.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>
#include <utility>
#include <vector>

#include "glint/image/film.hpp"
#include "glint/image/image_io.hpp"
#include "glint/import/importer.hpp"
#include "glint/params/diagnostics.hpp"
#include "glint/render/render.hpp"
#include "glint/scene/scene.hpp"
#include "glint/scene/scene_desc.hpp"
#include "glint/scene/scene_set.hpp"

namespace {

// A matte floor of albedo ρ = (0.2, 0.4, 0.6), seen from straight above under a sun of irradiance E = π
// that shines straight down: every pixel shows ρ/π · E cos 0 = ρ (docs/scene-format.md, `directional`).
const char* const kScene = R"(
render: {width: 32, height: 24, samples: 4}
camera: {type: orthographic, eye: [0, 5, 0], look_at: [0, 0, 0], height: 4}
materials:
  floor: {type: matte, albedo: [0.2, 0.4, 0.6]}
objects:
  - {type: plane, point: [0, 0, 0], normal: [0, 1, 0], material: floor}
lights:
  - {type: directional, direction: [0, -1, 0], irradiance: 3.14159265358979}
)";

}  // namespace

int main(int argc, char** argv) {
    try {
        // Step one, the description: a file of any format glint reads, or text. Paths inside the text
        // resolve against the folder given (here the working directory).
        glint::SceneDesc desc =
            argc > 1 ? glint::load_scene(argv[1]) : glint::parse_scene_text(kScene, "kScene", ".");
        // Step two, the built scene: edits of the description first (`--set` and the render flags),
        // all checked by the builder.
        const std::vector<std::string> sets(argv + std::min(argc, 3), argv + argc);
        const glint::Scene scene = glint::build_scene(std::move(desc), glint::RenderFlags{}, sets);

        // Step three, the render into a film of the scene's size, on all cores.
        glint::Film film(scene.view.settings.width, scene.view.settings.height);
        const glint::RenderStats stats = glint::render(scene, film);

        // The pixels: the mean of each pixel's samples, linear radiance.
        glint::Rgb sum;
        for (int y = 0; y < film.height(); ++y) {
            for (int x = 0; x < film.width(); ++x) {
                sum += film.pixel(x, y);
            }
        }
        const double pixels = static_cast<double>(film.width()) * film.height();
        std::printf("%d x %d pixels, %u samples per pixel, %.3f s\n", film.width(), film.height(),
                    stats.samples_per_pixel, stats.seconds);
        std::printf("mean radiance: %.6f %.6f %.6f\n", sum.r / pixels, sum.g / pixels, sum.b / pixels);
        if (argc > 2) {
            glint::write_image(film.to_image(), argv[2]);  // atomically; .png, .pfm or .exr
            std::printf("wrote %s\n", argv[2]);
        }
        return 0;
    } catch (const glint::SceneError& e) {
        std::fprintf(stderr, "%s\n", e.what());  // file:line:col: error: …, the line and a caret
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "glint_library_example: %s\n", e.what());
        return 1;
    }
}
