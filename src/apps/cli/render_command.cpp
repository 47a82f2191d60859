// `candela render`: validate the output path, load the scene, apply the command-line
// overrides, render with a progress bar and Ctrl-C support, write the image, report.
//
// Nothing is written to the output path unless the render completes: every check that can fail
// runs before rendering, and the image file is replaced atomically.
#include "apps/cli/render_command.h"

#include <cstdio>
#include <filesystem>
#include <memory>

#include "apps/cli/cli_error.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/progress_bar.h"
#include "apps/cli/summary.h"
#include "image/image_io.h"
#include "scene/scene_data.h"
#include "scene/scene_loader.h"

namespace fs = std::filesystem;

namespace candela::cli {

namespace {

std::string defaultOutputPath(const std::string& scene) {
  return (fs::path("out") / fs::path(scene).stem()).string() + ".png";
}

void checkOutputPath(const std::string& output) {
  if (isSupportedImagePath(output)) return;
  const std::string ext = fs::path(output).extension().string();
  throw CliError(kExitUsage, output + ": unsupported image format " +
                                 (ext.empty() ? std::string("(no extension)") : "'" + ext + "'") +
                                 ", expected .png, .exr or .pfm");
}

// Command-line values win over the scene file's.
void applyOverrides(const RenderOptions& options, SceneDesc* desc) {
  if (options.spp) desc->camera.spp = desc->render.spp = *options.spp;
  if (options.seed) desc->render.seed = *options.seed;
  if (options.maxDepth) desc->render.maxDepth = *options.maxDepth;
}

void createParentDirectories(const std::string& output) {
  const fs::path parent = fs::path(output).parent_path();
  std::error_code ec;
  if (parent.empty() || fs::is_directory(parent, ec)) return;
  fs::create_directories(parent, ec);
  if (ec)
    throw ImageWriteError(output + ": cannot create directory '" + parent.string() +
                          "': " + ec.message());
}

}  // namespace

CLI::App* addRenderCommand(CLI::App& app, RenderOptions* options) {
  CLI::App* cmd = app.add_subcommand("render", "Render a scene file to an image");
  cmd->add_option("scene", options->scene, "Scene file (JSON)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options->output,
                  "Output image: .png, .exr or .pfm (default: out/<scene name>.png)");
  cmd->add_option_function<uint32_t>(
         "--spp", [options](const uint32_t& v) { options->spp = v; }, "Samples per pixel")
      ->transform(decimalInteger(true));
  cmd->add_option_function<uint64_t>(
         "--seed", [options](const uint64_t& v) { options->seed = v; }, "Random seed")
      ->transform(decimalInteger(false));
  cmd->add_option_function<uint32_t>(
         "--max-depth", [options](const uint32_t& v) { options->maxDepth = v; },
         "Most surface interactions along a path")
      ->transform(decimalInteger(true));
  cmd->add_option("--threads", options->threads, "CPU worker threads (default: all cores)")
      ->transform(decimalInteger(true));
  cmd->add_option_function<std::string>(
         "--backend",
         [options](const std::string& name) { backendFromName(name, &options->backend); },
         "auto, cpu or cuda (default: auto)")
      ->check(backendChoice());
  cmd->add_flag("-q,--quiet", options->quiet, "No progress bar and no summary");
  return cmd;
}

int runRender(const RenderOptions& options) {
  const std::string output =
      options.output.empty() ? defaultOutputPath(options.scene) : options.output;
  checkOutputPath(output);
  std::string backendNote;
  const Backend backend = chooseBackend(options.backend, &backendNote);

  SceneDesc desc = loadSceneFile(options.scene);
  applyOverrides(options, &desc);
  const SceneData scene = flattenScene(desc);
  if (!backendNote.empty() && !options.quiet)
    std::fprintf(stderr, "candela: note: %s\n", backendNote.c_str());

  // Also covers the write: a late Ctrl-C must not leave a temporary file behind.
  InterruptGuard interrupt;
  std::unique_ptr<ProgressBar> bar;
  if (ProgressBar::wanted(options.quiet)) bar = std::make_unique<ProgressBar>(stderr);

  RenderControl control;
  control.sceneLabel = options.scene;
  control.threads = options.threads;
  control.cancel = &interrupt.flag();
  if (bar) control.progress = [&bar](double fraction) { bar->update(fraction); };
  const RenderResult result = renderScene(backend, scene, control);
  if (bar) bar->clear();

  if (result.cancelled) {
    std::fputs("candela: interrupted, no image written\n", stderr);
    return kExitInterrupted;
  }
  createParentDirectories(output);
  writeImage(output, result.image, desc.output);
  if (!options.quiet)
    std::printf("%s\n", renderSummary(output, scene.settings.spp, result).c_str());
  return kExitOk;
}

}  // namespace candela::cli
