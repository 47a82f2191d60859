// The seam between the CLI and the render backends: choosing one, and running it.
//
// chooseBackend is the one place that decides what `--backend auto` means and whether CUDA is
// available (the macro CANDELA_HAS_CUDA is defined only when the CUDA backend is built).
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>

#include "render/render_result.h"
#include "scene/frame_scene.h"
#include "scene/scene_data.h"

namespace candela::cli {

enum class Backend { Auto, Cpu, Cuda };

const char* backendName(Backend backend);

// "auto", "cpu" or "cuda" (any case); false for anything else.
bool backendFromName(const std::string& name, Backend* backend);

// Resolves Auto (CUDA when a usable GPU is present, else the CPU, with a one-line `note` saying
// why) and checks availability; throws CliError (exit 1) for a backend that cannot run here.
Backend chooseBackend(Backend requested, std::string* note);

struct RenderControl {
  int threads = 0;                            // CPU worker threads, 0: all cores
  std::function<void(double)> progress;       // fraction done, called serialised
  const std::atomic<bool>* cancel = nullptr;  // stop early when it becomes true
  std::string sceneLabel;                     // named in backend error messages
};

// Renders on a backend returned by chooseBackend.
RenderResult renderScene(Backend backend, const SceneData& scene, const RenderControl& control);

// Renders the frames of one sequence on one backend (from chooseBackend). On the GPU the scene
// stays resident between frames and each frame moves only what FrameScene says may have changed.
class FrameRenderer {
 public:
  explicit FrameRenderer(Backend backend);
  ~FrameRenderer();
  FrameRenderer(const FrameRenderer&) = delete;
  FrameRenderer& operator=(const FrameRenderer&) = delete;

  // `scene` is FrameScene's latest frame and `change` its preparation().
  RenderResult render(const SceneData& scene, FramePreparation change,
                      const RenderControl& control);

 private:
  struct Resident;
  Backend backend_;
  std::unique_ptr<Resident> resident_;
};

}  // namespace candela::cli
