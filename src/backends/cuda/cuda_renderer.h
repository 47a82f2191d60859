// The CUDA backend: the same integrator (render/render_pixel.h) compiled by nvcc.
//
// The scene is uploaded once into RAII device buffers; the accumulation buffer lives on the
// device and is read back once at the end. Rendering runs in progressive passes of a few
// samples per pixel, so progress and Ctrl-C are handled between passes without a CPU core
// spinning (the host waits on a blocking-sync event).
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <string>

#include "backends/cuda/cuda_error.h"
#include "render/render_result.h"
#include "render/sample_range.h"
#include "scene/frame_scene.h"
#include "scene/scene_data.h"

namespace candela {

// True when a usable CUDA device is present; otherwise `reason` says why not (e.g. "no CUDA
// device found" or the driver's error).
bool cudaBackendAvailable(std::string* reason);

struct CudaRenderOptions {
  uint32_t samplesPerPass = 4;
  std::function<void(double)> progress;  // fraction of samples done, from the calling thread
  const std::atomic<bool>* cancel = nullptr;
  std::string sceneLabel;  // named in error messages
  SampleRange samples;     // as in CpuRenderOptions: default all spp
};

// A scene resident on the GPU; upload once, render many times (animation, benchmarks).
class CudaScene {
 public:
  explicit CudaScene(const SceneData& scene);
  ~CudaScene();
  CudaScene(const CudaScene&) = delete;
  CudaScene& operator=(const CudaScene&) = delete;

  // Makes the device copy match `scene`, the next frame of the scene this one holds, moving only
  // what `change` says may differ (FrameScene's verdict): values (materials, spheres, lights,
  // camera and settings) always; vertices, normals and BVH nodes after a refit; everything after
  // a rebuild.
  void update(const SceneData& scene, FramePreparation change);

  // Throws CudaError (naming the scene and pass) on any CUDA failure.
  RenderResult render(const CudaRenderOptions& options) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace candela
