#include "apps/cli/devices_command.h"

#include <cstdio>
#include <string>
#include <vector>

#include "apps/cli/cli_error.h"
#include "backends/backend_report.h"

namespace candela::cli {

CLI::App* addDevicesCommand(CLI::App& app, DevicesOptions* options) {
  CLI::App* cmd = app.add_subcommand(
      "devices", "Print what each backend would render on here, and which one auto picks");
  cmd->add_option("--threads", options->threads, "CPU threads, as render's (default: all cores)")
      ->transform(decimalInteger(true, INT32_MAX));
  return cmd;
}

int runDevices(const DevicesOptions& options) {
  const std::vector<BackendReport> reports = reportBackends(options.threads);
  for (const BackendReport& r : reports)
    std::printf("%-5s %s\n", (std::string(r.backend) + ":").c_str(), r.summary.c_str());
  for (const BackendReport& r : reports)
    if (r.autoPicks) std::printf("auto: renders on the %s\n", r.backend);
  return kExitOk;
}

}  // namespace candela::cli
