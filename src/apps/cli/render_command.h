// `candela render SCENE [-o OUT] [--spp N] [--seed N] [--max-depth N] [--threads N]
//                       [--backend auto|cpu|cuda] [--quiet]`
#pragma once

#include <CLI/CLI.hpp>

#include "apps/cli/cli_options.h"

namespace candela::cli {

// Declares the subcommand and its options on `app`; parsing fills `options`.
CLI::App* addRenderCommand(CLI::App& app, RenderOptions* options);

// Loads, renders and writes the image; returns the exit code. Throws CliError, SceneError,
// ImageWriteError and std::exception for main() to report.
int runRender(const RenderOptions& options);

}  // namespace candela::cli
