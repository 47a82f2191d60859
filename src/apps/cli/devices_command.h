// `candela devices`: what each backend would render on here, or why it cannot, and which one
// `--backend auto` picks.
#pragma once

#include <CLI/CLI.hpp>

#include "apps/cli/cli_options.h"

namespace candela::cli {

CLI::App* addDevicesCommand(CLI::App& app, DevicesOptions* options);

// Prints one line per backend and one for `auto` on stdout; returns the exit code (0).
int runDevices(const DevicesOptions& options);

}  // namespace candela::cli
