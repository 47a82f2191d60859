// `candela render`: load and validate every scene, then either render one still (validate the
// output path, apply the command-line overrides, render with a progress bar and Ctrl-C support,
// write the image, report) or hand the scenes to the sequence renderer.
//
// Nothing is written unless the render completes: every check that can fail runs before rendering
// (output_check.h: no output replaces an input or another output, and each can be written), and
// the image and the --stats file are both written in full under temporary names beside their
// targets before either is renamed into place, so a failure leaves neither.
#include "apps/cli/render_command.h"

#include <tbb/task_arena.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <list>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include "apps/cli/cli_error.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/output_check.h"
#include "apps/cli/pass_files.h"
#include "apps/cli/progress_bar.h"
#include "apps/cli/scene_warnings.h"
#include "apps/cli/sequence_command.h"
#include "apps/cli/stats_writer.h"
#include "apps/cli/summary.h"
#include "apps/denoise/oidn_denoiser.h"
#include "backends/render_pilot.h"
#include "backends/thread_limit.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "scene/animation.h"
#include "scene/camera_crop.h"
#include "scene/flatten.h"
#include "scene/flow_motion.h"
#include "scene/mesh_layout.h"
#include "scene/read/scene_loader.h"

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

bool isFolderOutput(const std::string& output) {
  std::error_code ec;
  return !output.empty() && (output.back() == '/' || fs::is_directory(output, ec));
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

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int renderStill(const RenderCommandOptions& options, SceneDesc desc, double loadSeconds,
                const SceneDesc* next = nullptr, const SceneDesc* previous = nullptr);
int renderFrame(const RenderCommandOptions& options, const std::vector<SceneDesc>& scenes,
                double loadSeconds);

}  // namespace

CpuEngine chooseCpuEngine(const RenderCommandOptions& options, uint64_t triangles,
                          uint64_t spheres) {
  if (options.noBvh && options.cpuEngine == CpuEngine::Embree)
    throw CliError(kExitUsage,
                   "--no-bvh tests every primitive with candela's own engine; it cannot be "
                   "combined with --cpu-engine embree");
  return resolveCpuEngine(options.cpuEngine, options.noBvh, triangles, spheres);
}

std::unique_ptr<OidnDenoiser> loadDenoiser(const RenderCommandOptions& options) {
  if (!options.denoise) return nullptr;
  std::string whyNot;
  std::unique_ptr<OidnDenoiser> denoiser = OidnDenoiser::load(&whyNot);
  if (!denoiser) throw CliError(kExitUsage, whyNot);
  return denoiser;
}

double denoiseTimed(const OidnDenoiser* denoiser, RenderResult& result, const SceneData& scene,
                    Renderer& renderer, const RenderOptions& render) {
  if (!denoiser || result.cancelled) return 0;
  const auto start = std::chrono::steady_clock::now();
  denoiser->denoise(result, scene, renderer, render);
  return secondsSince(start);
}

PassFiles choosePassFiles(const RenderCommandOptions& options) {
  if (options.aovs.empty()) return {};
  try {
    return parsePassFiles(options.aovs);
  } catch (const std::invalid_argument& e) {
    throw CliError(kExitUsage, std::string("--aov: ") + e.what());
  }
}

// --crop's "X,Y,W,H"; a usage error where it is not four whole numbers.
CameraCrop parseCrop(const std::string& text) {
  const std::vector<std::string> parts = splitPassList(text);
  uint32_t values[4];
  bool ok = parts.size() == 4;
  for (size_t i = 0; ok && i < 4; ++i) {
    const std::string& part = parts[i];
    ok = !part.empty() && part.size() <= 10 &&
         part.find_first_not_of("0123456789") == std::string::npos &&
         std::stoull(part) <= UINT32_MAX;
    if (ok) values[i] = uint32_t(std::stoull(part));
  }
  if (!ok)
    throw CliError(kExitUsage,
                   "--crop: expected X,Y,WIDTH,HEIGHT in whole pixels (such as "
                   "128,64,256,256), got '" +
                       text + "'");
  return {values[0], values[1], values[2], values[3]};
}

void applyOverrides(const RenderCommandOptions& options, Backend backend, CpuEngine engine,
                    const std::vector<Aov>& aovs, SceneDesc* desc) {
  if (!options.crop.empty()) {
    const CameraCrop crop = parseCrop(options.crop);
    if (const std::optional<std::string> problem =
            cropProblem(crop, desc->camera.width, desc->camera.height))
      throw CliError(kExitUsage, "--crop: " + desc->file + ": " + *problem);
    desc->camera.crop = crop;
  }
  if (options.spp) desc->render.spp = *options.spp;
  if (options.seed) desc->render.seed = *options.seed;
  if (options.maxDepth) desc->render.maxDepth = *options.maxDepth;
  layOutForPasses(*desc, aovs);
  if (options.noBvh)
    desc->ownBvh = OwnBvh::Flat;
  else if (!needsOwnBvh(backend, engine))
    desc->ownBvh = OwnBvh::None;
}

CLI::App* addRenderCommand(CLI::App& app, RenderCommandOptions* options) {
  CLI::App* cmd = app.add_subcommand(
      "render", "Render a scene file to an image, or an animation or several files to frames");
  cmd->add_option("scenes", options->scenes,
                  "Scene files (JSON); several render as a sequence, one frame each")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", options->output,
                  "Output image: .png, .exr or .pfm (default: out/<scene name>.png); for a "
                  "sequence a folder (default: out/<first scene name>/)");
  cmd->add_option_function<uint32_t>(
         "--spp", [options](const uint32_t& v) { options->spp = v; }, "Samples per pixel")
      ->transform(decimalInteger(true, UINT32_MAX));
  cmd->add_option_function<uint64_t>(
         "--seed", [options](const uint64_t& v) { options->seed = v; }, "Random seed")
      ->transform(decimalInteger(false, UINT64_MAX));
  cmd->add_option_function<uint32_t>(
         "--max-depth", [options](const uint32_t& v) { options->maxDepth = v; },
         "Most surface interactions along a path")
      ->transform(decimalInteger(true, UINT32_MAX));
  cmd->add_option("--threads", options->threads,
                  "CPU threads for the whole run: loading, BVH build, render and denoiser "
                  "(default: all cores)")
      ->transform(decimalInteger(true, INT32_MAX));
  cmd->add_option_function<std::string>(
         "--backend",
         [options](const std::string& name) { backendFromName(name, &options->backend); },
         "auto, cpu or cuda (default: auto)")
      ->check(backendChoice());
  cmd->add_option_function<std::string>(
         "--cpu-engine",
         [options](const std::string& name) { cpuEngineFromName(name, &options->cpuEngine); },
         "Ray engine of the CPU backend: auto (Embree where the build has it), embree, or bvh "
         "(candela's own, the GPU's)")
      ->check(cpuEngineChoice());
  cmd->add_option("--crop", options->crop,
                  "Render only pixels X to X+W-1 and Y to Y+H-1 of the image (X,Y,W,H), each as "
                  "in the whole image's render; passes, camera file and frames likewise");
  cmd->add_flag("-q,--quiet", options->quiet, "No progress bar and no summary");
  cmd->add_option("--stats", options->stats,
                  "Also write the render's measured figures (load, BVH build, memory, rays, "
                  "samples/s, peak RSS) to this JSON file; single stills only");
  cmd->add_option("--aov", options->aovs,
                  "Render passes to write beside the image, comma-separated: " + knownAovNames() +
                      " (in an .exr as layers, else as sibling .pfm files: out.depth.pfm; alpha "
                      "as the image's A channel, in a .png too); "
                      "camera and poses write the camera's K and [R|t] and each instance's pose "
                      "beside them (out.camera.json, out.poses.json)");
  cmd->add_flag("--denoise", options->denoise,
                "Denoise the image with Intel Open Image Denoise, its direct and indirect light "
                "apart, guided by the albedo and normal passes (needs OIDN 2: pip install "
                "pyoidn)");
  cmd->add_flag("--no-bvh", options->noBvh,
                "Benchmarks only: test every primitive for every ray instead of using the BVH")
      ->group("");  // hidden from --help
  cmd->add_option_function<uint32_t>(
         "--frame", [options](const uint32_t& v) { options->frame = v; },
         "Render frame N of the scene's animation block as one image (to -o FILE), as a still")
      ->transform(decimalInteger(false, UINT32_MAX));
  cmd->add_option("--format", options->format, "Frame format of a sequence (default: png)")
      ->check(CLI::IsMember({"png", "exr", "pfm"}));
  cmd->add_option("--frames", options->frames,
                  "Render frames START:END of a sequence, END exclusive as in Python (10:20 is "
                  "frames 10 to 19); START: and :END also work (default: all)");
  cmd->add_flag("--overwrite", options->overwrite,
                "Render frames again that already exist (default: keep them, so a run resumes)");
  cmd->add_option("--video", options->video,
                  "Also encode the frames to this video with ffmpeg (H.264, e.g. out.mp4)");
  cmd->add_option_function<double>(
         "--fps", [options](const double& v) { options->fps = v; },
         "Frame rate of the video (default: the animation's fps, else 24)")
      ->check(finitePositiveNumber());
  return cmd;
}

int runRender(const RenderCommandOptions& options) {
  const ThreadLimit threadLimit(options.threads);  // from the loading on, not only the tiles
  // oneTBB starts its worker threads on first use; an empty task started now lets that happen
  // while the scenes load instead of inside the first parallel step, the BVH build
  // (docs/performance.md).
  tbb::this_task_arena::enqueue([] {});
  choosePassFiles(options);  // an unknown pass is refused before anything loads
  // Every scene is loaded and validated before anything renders or is written.
  const auto loadStart = std::chrono::steady_clock::now();
  std::vector<SceneDesc> scenes;
  for (const std::string& file : options.scenes) {
    scenes.push_back(loadSceneFile(file));
    printSceneWarnings(scenes.back());
  }
  const double loadSeconds = secondsSince(loadStart);
  if (options.frame) return renderFrame(options, scenes, loadSeconds);
  const bool sequence = scenes.size() > 1 || scenes[0].animation || options.sequenceOptionGiven() ||
                        isFolderOutput(options.output);
  if (sequence && !options.stats.empty())
    throw CliError(kExitUsage, "--stats works for a single still image, not for a sequence");
  if (sequence) return runSequence(options, std::move(scenes));
  return renderStill(options, std::move(scenes[0]), loadSeconds);
}

namespace {

// --frame N: the still of frame N, its flow pass towards frame N + 1 as a sequence's.
int renderFrame(const RenderCommandOptions& options, const std::vector<SceneDesc>& scenes,
                double loadSeconds) {
  const uint32_t frame = *options.frame;
  if (scenes.size() > 1)
    throw CliError(kExitUsage,
                   "--frame renders one frame of one scene's animation; several scene files are a "
                   "sequence (--frames picks some of its frames)");
  if (const char* name = options.sequenceOptionName())
    throw CliError(kExitUsage,
                   std::string("--frame renders one image; ") + name + " is for sequences");
  if (isFolderOutput(options.output))
    throw CliError(kExitUsage, "-o " + options.output +
                                   ": --frame renders one image, to a file (.png, .exr or .pfm)");
  const SceneDesc& animated = scenes[0];
  if (!animated.animation)
    throw CliError(kExitUsage, "--frame " + std::to_string(frame) + ": " + options.scenes[0] +
                                   " has no animation block");
  const uint32_t frames = animated.animation->frames;
  if (frame >= frames)
    throw CliError(kExitUsage, "--frame " + std::to_string(frame) + ": " + options.scenes[0] +
                                   " has " + std::to_string(frames) + " frames (0 to " +
                                   std::to_string(frames - 1) + ")");
  // --seed is the animation's seed, as in a sequence: the frame takes it + N.
  SceneDesc seeded = animated;
  if (options.seed) seeded.render.seed = *options.seed;
  RenderCommandOptions stillOptions = options;
  stillOptions.seed.reset();
  const SceneDesc next = sceneAtFrame(seeded, frame + 1);
  // Frame 0 has none before it: its backward flow is that of a still, 0.
  const SceneDesc previous = sceneAtFrame(seeded, frame > 0 ? frame - 1 : 0);
  return renderStill(stillOptions, sceneAtFrame(seeded, frame), loadSeconds, &next, &previous);
}

int renderStill(const RenderCommandOptions& options, SceneDesc desc, double loadSeconds,
                const SceneDesc* next, const SceneDesc* previous) {
  const std::string& sceneFile = options.scenes[0];
  const std::string output = options.output.empty() ? defaultOutputPath(sceneFile) : options.output;
  checkOutputPath(output);
  const PassFiles passes = choosePassFiles(options);
  std::vector<OutputFile> outputs = {
      {options.output.empty() ? "the default output" : "-o", output}};
  for (const std::string& pass : passFilePaths(output, passes)) outputs.push_back({"--aov", pass});
  if (!options.stats.empty()) outputs.push_back({"--stats", options.stats});
  checkOutputFiles(outputs, inputFiles({desc}));
  const Backend backend = chooseBackend(options.backend);
  const CpuEngine engine = chooseCpuEngine(options, triangleCount(desc), sphereCount(desc));

  const std::unique_ptr<OidnDenoiser> denoiser = loadDenoiser(options);
  applyOverrides(options, backend, engine, passes.aovs, &desc);
  const auto flattenStart = std::chrono::steady_clock::now();
  // A still does not move: its flow passes are 0 (and NaN nowhere, as both cameras are one). A
  // frame of an animation moves towards the next, and from the previous.
  std::optional<FlowMotion> flow, backwardFlow;
  if (hasAov(passes.aovs, Aov::Flow)) flow = flowMotion(desc, next ? *next : desc);
  if (hasAov(passes.aovs, Aov::BackwardFlow))
    backwardFlow = flowMotion(desc, previous ? *previous : desc);
  // Flattening lets go of the meshes but for the poses file, which gives each model's box.
  SceneData scene = passes.poses ? flattenScene(desc) : flattenScene(std::move(desc));
  if (flow) applyFlowMotion(scene, *flow);
  if (backwardFlow) applyFlowMotion(scene, *backwardFlow, FlowDirection::Backward);
  const double flattenSeconds = secondsSince(flattenStart);

  // Also covers the write: a late Ctrl-C must not leave a temporary file behind.
  InterruptGuard interrupt;
  std::unique_ptr<ProgressBar> bar;
  if (ProgressBar::wanted(options.quiet)) bar = std::make_unique<ProgressBar>(stderr);

  RenderOptions render;
  render.sceneLabel = sceneFile;
  render.threads = options.threads;
  render.cancel = &interrupt.flag();
  render.aovs = !passes.aovs.empty() || denoiser;
  if (bar) render.progress = [&bar](double fraction) { bar->update(fraction); };
  const std::unique_ptr<Renderer> renderer = makeRenderer(backend, engine);
  renderer->setScene(scene, SceneChange::Structure);
  PilotChoice pilot;
  RenderResult result = renderWithPilot(*renderer, scene, render, &pilot);
  if (bar) bar->clear();
  const double denoiseSeconds = denoiseTimed(denoiser.get(), result, scene, *renderer, render);

  if (result.cancelled) {
    std::fputs("candela: interrupted, no image written\n", stderr);
    return kExitInterrupted;
  }
  createParentDirectories(output);
  std::list<StagedFile> images;  // the image and its pass files, all or none
  for (const auto& [path, bytes] : encodeWithPasses(output, result, scene, passes, desc))
    images.emplace_back(path, bytes);
  std::optional<StagedFile> stats;
  if (!options.stats.empty()) {
    RenderStats info;
    info.scene = sceneFile;
    info.backend = backendName(backend);
    info.threads = options.threads;
    info.useBvh = !options.noBvh;
    info.loadSeconds = loadSeconds;
    info.flattenSeconds = flattenSeconds;
    info.denoiseSeconds = denoiseSeconds;
    info.acceleration = renderer->acceleration();
    info.pilot = pilot;
    createParentDirectories(options.stats);
    stats.emplace(options.stats, renderStatsJson(info, scene, result));
  }
  for (StagedFile& file : images) file.commit();
  if (stats) stats->commit();
  if (!options.quiet)
    std::printf("%s\n", renderSummary(output, scene.settings.spp, result, denoiseSeconds).c_str());
  return kExitOk;
}

}  // namespace

}  // namespace candela::cli
