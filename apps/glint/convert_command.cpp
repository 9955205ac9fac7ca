// `glint convert FILE -o scene.yaml`: any scene glint opens, written as glint's YAML. Rendering the
// written file builds the same tree as rendering FILE, so the same image, bit for bit; the warnings
// of the import are printed, since the YAML no longer shows where a value was approximated.
#include <filesystem>
#include <iostream>
#include <memory>
#include <vector>

#include "commands.hpp"
#include "glint/image/image_io.hpp"
#include "glint/import/importer.hpp"

namespace {

constexpr int kExitBadInput = 2;

struct ConvertOptions {
    std::string scene_path;
    std::string output;
    glint::ImportOptions import;
};

int run_convert(const ConvertOptions& options) {
    const std::filesystem::path output =
        options.output.empty() ? std::filesystem::path(options.scene_path).stem().string() + ".yaml"
                               : options.output;
    std::string yaml;
    try {
        const glint::SceneDesc desc = glint::load_scene(options.scene_path, options.import);
        print_warnings(desc);
        const std::filesystem::path folder = output.parent_path().empty() ? "." : output.parent_path();
        yaml = "# Converted by glint convert from " +
               std::filesystem::path(options.scene_path).filename().string() + "\n" +
               glint::scene_yaml_for(desc, folder);
    } catch (const glint::SceneError& e) {
        std::cerr << e.what() << '\n';
        return kExitBadInput;
    }
    try {
        glint::write_file_atomically(output, std::vector<unsigned char>(yaml.begin(), yaml.end()));
    } catch (const std::exception& e) {
        std::cerr << "glint: error: " << e.what() << '\n';
        return 1;
    }
    std::cerr << "glint: wrote " << output.string() << '\n';
    return 0;
}

}  // namespace

void add_convert_command(CLI::App& app) {
    auto options = std::make_shared<ConvertOptions>();
    CLI::App* convert = app.add_subcommand(
        "convert", "Write a scene of another tool (" + glint::importer_formats() + ") as a glint YAML scene");
    convert->add_option("scene", options->scene_path, "The scene file to convert")->required();
    convert->add_option("-o,--output", options->output, "The YAML file to write; default: <scene>.yaml");
    convert->add_option("--camera", options->import.camera,
                        "glTF scenes: the camera to look through, by name");
    convert->callback([options] {
        if (const int code = run_convert(*options); code != 0) {
            throw CLI::RuntimeError(code);
        }
    });
}
