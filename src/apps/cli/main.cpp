// candela's command-line entry point: parses the command line and turns every failure into a
// one-line message on stderr and an exit code (0 ok, 1 render/IO failure, 2 bad usage or bad
// scene, 130 interrupted). No exception ever escapes, so no stack trace is ever printed.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <new>

#include "apps/cli/cli_error.h"
#include "apps/cli/cli_options.h"
#include "apps/cli/devices_command.h"
#include "apps/cli/info_command.h"
#include "apps/cli/render_command.h"
#include "apps/cli/version.h"
#include "backends/backend_error.h"
#include "image/image_io.h"
#include "scene/scene_error.h"

namespace {

using namespace candela::cli;

int fail(ExitCode code, const char* message) {
  std::fprintf(stderr, "candela: error: %s\n", message);
  return code;
}

// Runs the chosen subcommand and maps each kind of error to its exit code.
int dispatch(CLI::App& app, CLI::App* render, const RenderCommandOptions& renderOptions, CLI::App* info,
             const InfoOptions& infoOptions, CLI::App* devices, const DevicesOptions& devicesOptions) {
  try {
    if (render->parsed()) return runRender(renderOptions);
    if (info->parsed()) return runInfo(infoOptions);
    if (devices->parsed()) return runDevices(devicesOptions);
    std::fputs(app.help().c_str(), stderr);  // no subcommand
    return kExitUsage;
  } catch (const CliError& e) {
    return fail(e.code(), e.what());
  } catch (const candela::SceneError& e) {
    return fail(kExitUsage, e.what());
  } catch (const candela::ImageWriteError& e) {
    return fail(kExitFailure, e.what());
  } catch (const candela::BackendError& e) {
    return fail(kExitFailure, e.what());
  } catch (const std::bad_alloc&) {
    return fail(kExitFailure,
                "out of memory (the scene or the image is too large for this machine)");
  } catch (const std::exception& e) {
    return fail(kExitFailure, e.what());
  } catch (...) {
    return fail(kExitFailure, "unexpected internal error");
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app("candela: a physically based path tracer", "candela");
  app.set_version_flag("--version", std::string("candela ") + kVersion);
  app.require_subcommand(0, 1);
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("candela: error: ") + e.what() + "\nRun with --help for usage.\n";
  });

  RenderCommandOptions renderOptions;
  InfoOptions infoOptions;
  DevicesOptions devicesOptions;
  CLI::App* render = addRenderCommand(app, &renderOptions);
  CLI::App* info = addInfoCommand(app, &infoOptions);
  CLI::App* devices = addDevicesCommand(app, &devicesOptions);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Help and version requests are "errors" with exit code 0; real ones are usage errors.
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  }
  return dispatch(app, render, renderOptions, info, infoOptions, devices, devicesOptions);
}
