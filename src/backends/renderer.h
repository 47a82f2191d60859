// The one seam between the apps and the render backends.
//
// A Renderer holds a scene and renders it, as often as asked; between renders it may be given the
// next frame of an animation with what changed (render/scene_change.h), which a backend that keeps
// the scene resident (the GPU) uses to move only what may differ. The CPU and CUDA backends
// implement it with the same input; makeRenderer picks one, and chooseBackend is the one place
// that decides what `auto` means.
#pragma once

#include <memory>
#include <string>

#include "backends/backend_error.h"
#include "backends/cpu/cpu_engine.h"
#include "backends/render_options.h"
#include "render/render_result.h"
#include "render/scene_change.h"
#include "render/scene_data.h"

namespace candela {

enum class Backend { Auto, Cpu, Cuda };

const char* backendName(Backend backend);

// "auto", "cpu" or "cuda" (any case); false for anything else.
bool backendFromName(const std::string& name, Backend* backend);

// Whether this build has the CUDA backend and a usable GPU is present; `reason` says why not.
bool cudaUsable(std::string* reason);

// Resolves Auto to the GPU where cudaUsable, else to the CPU (the CUDA backend passed its parity
// check on a GPU: docs/performance.md, CUDA backend), and checks that the backend can run here:
// BackendError otherwise.
Backend chooseBackend(Backend requested);

// The ray engine a renderer traces with and what its own acceleration structure cost.
struct AccelerationStats {
  const char* engine = "bvh";  // "bvh": candela's own, built with the scene (SceneData::bvh)
  double buildSeconds = 0;     // the engine's own build in the last setScene (0 for "bvh")
  uint64_t bytes = 0;          // the engine's own memory (0 for "bvh")
  // The instruction set the CPU backend's render loop runs in (backends/cpu/tile_renderer.h):
  // "x86-64" or "x86-64-v4"; "" on the GPU.
  const char* isa = "";
};

class Renderer {
 public:
  virtual ~Renderer() = default;

  // Makes `scene` the one rendered next; it must stay alive and unchanged until the next call.
  // `change` is what may differ from the scene given last; the first call takes everything.
  virtual void setScene(const SceneData& scene, SceneChange change) = 0;

  // Renders the scene given last. Throws BackendError on a failure of the device.
  virtual RenderResult render(const RenderOptions& options) = 0;

  virtual AccelerationStats acceleration() const { return {}; }
};

// Whether the scene given to a renderer of `backend` with `cpuEngine` must carry candela's own
// BVH: every engine but the CPU's Embree, which builds its own, traces it.
bool needsOwnBvh(Backend backend, CpuEngine cpuEngine);

// A renderer on `backend`, which chooseBackend returned; the CPU traces with `cpuEngine`, which
// resolveCpuEngine returned (the GPU ignores it: it always runs candela's own BVH).
std::unique_ptr<Renderer> makeRenderer(Backend backend, CpuEngine cpuEngine);

}  // namespace candela
