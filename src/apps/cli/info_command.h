// `candela info SCENE`: what a scene contains and how its BVH came out.
#pragma once

#include <CLI/CLI.hpp>

#include "apps/cli/cli_options.h"

namespace candela::cli {

CLI::App* addInfoCommand(CLI::App& app, InfoOptions* options);

// Prints the report on stdout and returns the exit code; errors are thrown for main().
int runInfo(const InfoOptions& options);

}  // namespace candela::cli
