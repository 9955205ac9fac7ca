// The subcommands that live in their own files. Each adds itself to the app; it does its work in its
// CLI11 callback and reports failure by printing a message and throwing CLI::RuntimeError(exit code),
// which main() turns into the process exit code (2 bad input, 1 other failure).
#pragma once

#include <CLI/CLI.hpp>
#include <iostream>

#include "glint/scene/scene_desc.hpp"

// `glint samples`: draw, list and measure sample patterns (samples_command.cpp).
void add_samples_command(CLI::App& app);
// `glint serve`: a live preview in the browser (serve_command.cpp).
void add_serve_command(CLI::App& app);
// `glint info SCENE`: what the scene holds and what its BVH costs (info_command.cpp).
void add_info_command(CLI::App& app);
// `glint convert FILE -o scene.yaml`: another tool's scene as a glint YAML file (convert_command.cpp).
void add_convert_command(CLI::App& app);
// `glint merge PART... -o IMAGE`: the parts of `glint render --tile I/N` as one image (merge_command.cpp).
void add_merge_command(CLI::App& app);

// Prints what an importer approximated or left out, one positioned warning each, to stderr.
inline void print_warnings(const glint::SceneDesc& desc) {
    for (const glint::SceneWarning& warning : desc.warnings) {
        std::cerr << warning.to_string() << '\n';
    }
}
