// Rendering a sequence of frames; see sequence_command.h.
#include "apps/cli/sequence_command.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <list>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "apps/cli/cli_error.h"
#include "apps/cli/interrupt.h"
#include "apps/cli/output_check.h"
#include "apps/cli/pass_files.h"
#include "apps/cli/progress_bar.h"
#include "apps/cli/render_command.h"
#include "apps/cli/summary.h"
#include "apps/cli/video.h"
#include "apps/denoise/oidn_denoiser.h"
#include "backends/render_pilot.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "scene/animation.h"
#include "scene/flow_motion.h"
#include "scene/frame_scene.h"
#include "scene/scene_error.h"

namespace fs = std::filesystem;

namespace candela::cli {
namespace {

struct FrameRange {
  uint32_t begin = 0, end = 0;  // [begin, end)
};

// "A:B" (end exclusive), "A:", ":B", ":" or "A" (that frame alone), within [0, count).
FrameRange parseFrames(const std::string& text, uint32_t count) {
  if (text.empty()) return {0, count};
  const auto usage = [&] {
    return CliError(kExitUsage, "--frames " + text +
                                    ": expected START:END (END exclusive, e.g. 0:10), START:, "
                                    ":END or one frame number");
  };
  const auto number = [&](const std::string& s, uint32_t fallback) -> uint32_t {
    if (s.empty()) return fallback;
    if (s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos) throw usage();
    return uint32_t(std::stoul(s));
  };
  FrameRange range;
  const size_t colon = text.find(':');
  if (colon == std::string::npos) {
    range.begin = number(text, 0);
    range.end = range.begin + 1;
  } else {
    range.begin = number(text.substr(0, colon), 0);
    range.end = number(text.substr(colon + 1), count);
  }
  if (range.begin >= range.end)
    throw CliError(kExitUsage, "--frames " + text +
                                   ": the range is empty (START must be below END, which is "
                                   "exclusive)");
  if (range.end > count)
    throw CliError(kExitUsage, "--frames " + text + ": there are " + std::to_string(count) +
                                   " frames, numbered 0 to " + std::to_string(count - 1));
  return range;
}

// Enough digits for the last frame, at least four: frame_0000.png.
int frameDigits(uint32_t count) {
  int digits = 1;
  for (uint32_t n = count - 1; n >= 10; n /= 10) ++digits;
  return digits < 4 ? 4 : digits;
}

std::string framePath(const std::string& dir, uint32_t frame, int digits,
                      const std::string& format) {
  char name[64];
  std::snprintf(name, sizeof name, "frame_%0*u.%s", digits, frame, format.c_str());
  return (fs::path(dir) / name).string();
}

// The frame that `file` is, when it is one of the frames [range) that this run writes in `dir`.
std::optional<uint32_t> frameOf(const std::string& file, const std::string& dir, FrameRange range,
                                int digits, const std::string& format) {
  const fs::path path(file);
  const std::string name = path.filename().string();
  const std::string prefix = "frame_", suffix = "." + format;
  if (name.size() != prefix.size() + size_t(digits) + suffix.size() ||
      name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return std::nullopt;
  const std::string number = name.substr(prefix.size(), size_t(digits));
  if (number.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
  const uint32_t frame = uint32_t(std::stoul(number));
  if (frame < range.begin || frame >= range.end) return std::nullopt;
  const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  if (!sameFile(folder.string(), dir)) return std::nullopt;
  return frame;
}

// Whether a frame's file is whole: an image (isCompleteImageFile) or, for the tables beside it
// (the instance names, the camera), a JSON document.
bool isCompleteFrameFile(const std::string& path) {
  if (fs::path(path).extension() != ".json") return isCompleteImageFile(path);
  std::ifstream in(path);
  return in && nlohmann::json::accept(in);
}

// The "formats" a frame's files end in: "png", and for passes beside it "depth.pfm", ...
std::vector<std::string> frameSuffixes(const std::string& format, const PassFiles& passes) {
  std::vector<std::string> suffixes = {format};
  for (const std::string& pass : passFilePaths("frame." + format, passes))
    suffixes.push_back(pass.substr(std::string("frame.").size()));
  return suffixes;
}

// Where the sequence writes, checked before anything renders (output_check.h): the frame folder
// can be made and written in, no frame replaces a file the scenes read, and the video replaces
// neither an input nor a frame.
void checkSequenceOutputs(const RenderCommandOptions& options, const std::vector<SceneDesc>& scenes,
                          const std::string& dir, FrameRange range, int digits,
                          const std::vector<std::string>& suffixes) {
  const std::string reason = unwritableReason(dir, true);
  if (!reason.empty())
    throw CliError(kExitFailure, dir + ": cannot write the frames there: " + reason);
  const std::vector<InputFile> inputs = inputFiles(scenes);
  for (const std::string& format : suffixes)
    for (const InputFile& in : inputs)
      if (const std::optional<uint32_t> frame = frameOf(in.path, dir, range, digits, format))
        throw CliError(kExitUsage, in.path + ": frame " + std::to_string(*frame) +
                                       " of the sequence would overwrite " + in.kind +
                                       ", which the render reads");
  if (options.video.empty()) return;
  if (sameFile(options.video, dir))
    throw CliError(kExitUsage, options.video + ": --video names the folder of the frames");
  checkOutputFiles({{"--video", options.video}}, inputs);
  for (const std::string& format : suffixes)
    if (const std::optional<uint32_t> frame = frameOf(options.video, dir, range, digits, format))
      throw CliError(kExitUsage, options.video + ": --video would overwrite frame " +
                                     std::to_string(*frame) + " of the sequence");
}

// The checks that need every scene: no animation block inside a sequence of files, and one image
// size for a video.
void checkScenes(const RenderCommandOptions& options, const std::vector<SceneDesc>& scenes) {
  if (scenes.size() > 1)
    for (const SceneDesc& s : scenes)
      if (s.animation)
        throw SceneError(s.file +
                         ": animation: a scene with an animation block is rendered on its own, "
                         "not in a sequence of scene files");
  if (options.video.empty()) return;
  if (!options.format.empty() && options.format != "png")
    throw CliError(kExitUsage,
                   "--video needs PNG frames (ffmpeg encodes the 8-bit images), got "
                   "--format " +
                       options.format);
  for (const SceneDesc& s : scenes)
    if (s.camera.width != scenes[0].camera.width || s.camera.height != scenes[0].camera.height)
      throw CliError(kExitUsage,
                     "--video: every frame must have the same size, but " + scenes[0].file +
                         " is " + std::to_string(scenes[0].camera.width) + "x" +
                         std::to_string(scenes[0].camera.height) + " and " + s.file + " is " +
                         std::to_string(s.camera.width) + "x" + std::to_string(s.camera.height));
}

// How a frame's scene was prepared, for the per-frame summary line.
const char* preparationName(SceneChange change) {
  switch (change) {
    case SceneChange::Values:
      return "and BVH reused";
    case SceneChange::Motion:
      return "moved, BVH refitted";
    case SceneChange::Structure:
      break;
  }
  return "flattened, BVH built";
}

}  // namespace

int runSequence(const RenderCommandOptions& options, std::vector<SceneDesc> scenes) {
  checkScenes(options, scenes);
  const bool animated = scenes.size() == 1 && scenes[0].animation;
  const uint32_t count = animated ? scenes[0].animation->frames : uint32_t(scenes.size());
  const std::string format = options.format.empty() ? "png" : options.format;
  const std::string dir = options.output.empty()
                              ? (fs::path("out") / fs::path(options.scenes[0]).stem()).string()
                              : options.output;
  if (isSupportedImagePath(dir)) {
    // One still scene with -o to an image is a sequence only because a sequence option was given.
    if (!animated && scenes.size() == 1)
      throw CliError(kExitUsage, std::string(options.sequenceOptionName()) +
                                     " is an option of sequences (an animated scene or several "
                                     "scene files), and " +
                                     options.scenes[0] + " is one still image (-o " + dir +
                                     "): leave it out");
    throw CliError(kExitUsage, "-o " + dir +
                                   ": a sequence is written to a folder (e.g. -o frames/), not "
                                   "to one image");
  }
  const FrameRange range = parseFrames(options.frames, count);
  const PassFiles passes = choosePassFiles(options);
  const bool wantsFlow = hasAov(passes.aovs, Aov::Flow);
  const bool wantsBackwardFlow = hasAov(passes.aovs, Aov::BackwardFlow);
  // The flow passes follow one scene's animation to its next (or previous) frame; separate files
  // say nothing of how their entities correspond.
  if ((wantsFlow || wantsBackwardFlow) && scenes.size() > 1)
    throw CliError(kExitUsage, std::string("--aov ") + (wantsFlow ? "flow" : "backward_flow") +
                                   ": the flow passes are the motion of one animated scene; a "
                                   "sequence of several scene files has none (render them one "
                                   "by one, or as one animation)");
  const std::vector<std::string> suffixes = frameSuffixes(format, passes);
  const std::unique_ptr<OidnDenoiser> denoiser = loadDenoiser(options);
  const Backend backend = chooseBackend(options.backend);
  uint64_t triangles = 0, spheres = 0;
  for (const SceneDesc& scene : scenes) {
    triangles = std::max(triangles, triangleCount(scene));
    spheres = std::max(spheres, sphereCount(scene));
  }
  const CpuEngine engine = chooseCpuEngine(options, triangles, spheres);
  for (SceneDesc& scene : scenes) applyOverrides(options, backend, engine, passes.aovs, &scene);

  const int digits = frameDigits(count);
  checkSequenceOutputs(options, scenes, dir, range, digits, suffixes);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw ImageWriteError(dir + ": cannot create the frame folder: " + ec.message());
  std::vector<uint32_t> todo;
  // A frame counts as done only when its file is whole; what a killed run left half-written
  // beside it (a temporary file of a process that is gone) is cleared away.
  removeStaleTemporaryFiles(dir);
  // A frame is done when its image and every pass file beside it are.
  for (uint32_t f = range.begin; f < range.end; ++f) {
    bool done = !options.overwrite;
    for (const std::string& suffix : suffixes)
      done = done && isCompleteFrameFile(framePath(dir, f, digits, suffix));
    if (!done) todo.push_back(f);
  }
  const uint32_t kept = range.end - range.begin - uint32_t(todo.size());
  if (!options.quiet) {
    if (kept > 0)
      std::printf("%s: %u of %u frames exist and are kept (--overwrite renders them again)\n",
                  dir.c_str(), kept, range.end - range.begin);
  }

  InterruptGuard interrupt;
  std::unique_ptr<ProgressBar> bar;
  if (ProgressBar::wanted(options.quiet)) bar = std::make_unique<ProgressBar>(stderr);
  FrameScene frameScene;
  const std::unique_ptr<Renderer> renderer = makeRenderer(backend, engine);
  const auto start = std::chrono::steady_clock::now();
  for (size_t k = 0; k < todo.size(); ++k) {
    const uint32_t frame = todo[k];
    const SceneDesc still = sceneAtFrame(animated ? scenes[0] : scenes[frame], frame);
    std::optional<FlowMotion> flow, backwardFlow;
    if (wantsFlow) flow = flowMotion(still, sceneAtFrame(scenes[0], frame + 1));
    // Frame 0 has none before it: its backward flow is that of a still, 0.
    if (wantsBackwardFlow)
      backwardFlow = flowMotion(still, sceneAtFrame(scenes[0], frame > 0 ? frame - 1 : 0));
    const SceneData& data =
        frameScene.prepare(still, flow ? &*flow : nullptr, backwardFlow ? &*backwardFlow : nullptr);
    if (bar)
      bar->startFrame("frame " + std::to_string(frame) + " (" + std::to_string(k + 1) + "/" +
                          std::to_string(todo.size()) + ")",
                      unsigned(k), unsigned(todo.size()));
    RenderOptions render;
    render.sceneLabel = still.file;
    render.threads = options.threads;
    render.cancel = &interrupt.flag();
    render.aovs = !passes.aovs.empty() || denoiser;
    if (bar) render.progress = [&bar](double fraction) { bar->update(fraction); };
    renderer->setScene(data, frameScene.change());
    RenderResult result = renderWithPilot(*renderer, data, render);
    if (bar) bar->clear();
    const double denoiseSeconds = denoiseTimed(denoiser.get(), result, data, *renderer, render);
    if (result.cancelled) {
      std::fprintf(stderr,
                   "candela: interrupted during frame %u; the %zu frames finished are kept, run "
                   "the same command again to resume\n",
                   frame, k);
      return kExitInterrupted;
    }
    const std::string path = framePath(dir, frame, digits, format);
    std::list<StagedFile> files;  // the frame and its pass files, all or none
    for (const auto& [file, bytes] : encodeWithPasses(path, result, data, passes, still))
      files.emplace_back(file, bytes);
    for (StagedFile& file : files) file.commit();
    if (!options.quiet) {
      std::printf("%s (scene %s in %.3f ms)\n",
                  renderSummary(path, data.settings.spp, result, denoiseSeconds).c_str(),
                  preparationName(frameScene.change()), frameScene.seconds() * 1e3);
      std::fflush(stdout);
    }
  }
  if (!options.quiet)
    std::printf("%s: %zu frames rendered, %u kept, %.2f s\n", dir.c_str(), todo.size(), kept,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());

  if (!options.video.empty()) {
    VideoJob job;
    job.folder = dir;
    job.digits = digits;
    job.first = range.begin;
    job.count = range.end - range.begin;
    job.fps = options.fps ? *options.fps : (animated ? scenes[0].animation->fps : 24.0);
    job.output = options.video;
    encodeVideo(job);
    if (!options.quiet)
      std::printf("%s: %u frames at %g fps\n", job.output.c_str(), job.count, job.fps);
  }
  return kExitOk;
}

}  // namespace candela::cli
