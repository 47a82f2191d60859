// Backend choice and dispatch for the CLI.
#include "apps/cli/backend.h"

#include <cctype>
#include <cstring>
#include <memory>
#include <string>

#include "apps/cli/cli_error.h"
#include "backends/cpu/cpu_renderer.h"

#if defined(CANDELA_HAS_CUDA)
#include "backends/cuda/cuda_renderer.h"
#endif

namespace candela::cli {

const char* backendName(Backend backend) {
  switch (backend) {
    case Backend::Auto:
      return "auto";
    case Backend::Cpu:
      return "cpu";
    case Backend::Cuda:
      return "cuda";
  }
  return "?";
}

bool backendFromName(const std::string& name, Backend* backend) {
  for (Backend b : {Backend::Auto, Backend::Cpu, Backend::Cuda}) {
    if (name.size() != std::strlen(backendName(b))) continue;
    bool same = true;
    for (size_t i = 0; i < name.size(); ++i)
      same = same && std::tolower((unsigned char)name[i]) == backendName(b)[i];
    if (same) {
      *backend = b;
      return true;
    }
  }
  return false;
}

Backend chooseBackend(Backend requested, std::string* note) {
  switch (requested) {
    case Backend::Auto: {
#if defined(CANDELA_HAS_CUDA)
      std::string reason;
      if (cudaBackendAvailable(&reason)) return Backend::Cuda;
      if (note) *note = "no usable GPU (" + reason + "), rendering on the CPU";
#else
      (void)note;  // a CPU-only build has nothing to fall back from
#endif
      return Backend::Cpu;
    }
    case Backend::Cpu:
      return Backend::Cpu;
    case Backend::Cuda: {
#if defined(CANDELA_HAS_CUDA)
      std::string reason;
      if (!cudaBackendAvailable(&reason))
        throw CliError(kExitFailure, "--backend cuda: no usable GPU: " + reason);
      return Backend::Cuda;
#else
      throw CliError(kExitFailure,
                     "the CUDA backend is not available in this build (configure with "
                     "-DCANDELA_CUDA=ON on a machine with the CUDA toolkit)");
#endif
    }
  }
  return Backend::Cpu;
}

// A still is a sequence of one frame.
RenderResult renderScene(Backend backend, const SceneData& scene, const RenderControl& control) {
  return FrameRenderer(backend).render(scene, FramePreparation::Built, control);
}

struct FrameRenderer::Resident {
#if defined(CANDELA_HAS_CUDA)
  std::unique_ptr<CudaScene> gpuScene;
#endif
};

FrameRenderer::FrameRenderer(Backend backend) : backend_(backend), resident_(new Resident) {}
FrameRenderer::~FrameRenderer() = default;

RenderResult FrameRenderer::render(const SceneData& scene, FramePreparation change,
                                   const RenderControl& control) {
  if (backend_ != Backend::Cuda) {
    CpuRenderOptions options;
    options.threads = control.threads;
    options.progress = control.progress;
    options.cancel = control.cancel;
    return renderCpu(scene.view(), options);
  }
#if defined(CANDELA_HAS_CUDA)
  try {
    std::unique_ptr<CudaScene>& gpuScene = resident_->gpuScene;
    if (gpuScene) {
      gpuScene->update(scene, change);
    } else {
      gpuScene = std::make_unique<CudaScene>(scene);
    }
    CudaRenderOptions options;
    options.progress = control.progress;
    options.cancel = control.cancel;
    options.sceneLabel = control.sceneLabel;
    return gpuScene->render(options);
  } catch (const CudaError& e) {
    resident_->gpuScene.reset();  // a failed update leaves the device copy unknown
    throw CliError(kExitFailure, e.what());
  }
#else
  (void)change;
#endif
  throw CliError(kExitFailure, std::string("the ") + backendName(backend_) +
                                   " backend is not available in this build");
}

}  // namespace candela::cli
