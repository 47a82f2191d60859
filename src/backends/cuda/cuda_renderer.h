// The CUDA backend: the same integrator (render/render_pixel.h) compiled by nvcc.
//
// The scene is uploaded into RAII device buffers and stays resident between renders; a new frame
// moves only the arrays its change may rewrite, and the environment map's arrays and the light
// tree only when their contents differ from the ones on the device. The accumulation buffer lives
// on the device and is read back once at the end. Rendering runs in progressive passes of a few
// samples per pixel, so progress and Ctrl-C are handled between passes without a CPU core spinning
// (the host waits on a blocking-sync event).
#pragma once

#include <memory>
#include <string>

#include "backends/cuda/cuda_error.h"
#include "backends/renderer.h"

namespace candela {

// True when a usable CUDA device is present; otherwise `reason` says why not (e.g. "no CUDA
// device found" or the driver's error).
bool cudaBackendAvailable(std::string* reason);

// The device the backend renders on, for people: its name, memory, compute capability and the
// driver's and runtime's versions. Call only where cudaBackendAvailable is true.
std::string cudaDeviceSummary();

class CudaRenderer final : public Renderer {
 public:
  CudaRenderer();  // throws CudaError without a usable device
  ~CudaRenderer() override;

  // Uploads what `change` may have rewritten, and the keyed groups whose keys differ from the
  // device's (all of it on the first call). After a failure the
  // device copy is unknown, so the next call uploads everything again.
  void setScene(const SceneData& scene, SceneChange change) override;

  // Throws CudaError (naming the scene and pass) on any CUDA failure.
  RenderResult render(const RenderOptions& options) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace candela
