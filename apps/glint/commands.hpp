// Subcommands of the glint tool that live in their own files: each adds itself to the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

// `glint serve`: a live preview in the browser (serve_command.cpp).
void add_serve_command(CLI::App& app);
