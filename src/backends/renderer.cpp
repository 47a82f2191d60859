// Backend choice and the factory of renderers; see renderer.h.
#include "backends/renderer.h"

#include <cctype>
#include <cstring>

#include "backends/cpu/cpu_renderer.h"

#if defined(CANDELA_HAS_CUDA)
#include "backends/cuda/cuda_renderer.h"
#endif

namespace candela {

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

bool cudaUsable(std::string* reason) {
#if defined(CANDELA_HAS_CUDA)
  return cudaBackendAvailable(reason);
#else
  if (reason)
    *reason =
        "this build has no CUDA backend (configure with -DCANDELA_CUDA=ON on a "
        "machine with the CUDA toolkit)";
  return false;
#endif
}

Backend chooseBackend(Backend requested) {
  std::string reason;
  switch (requested) {
    case Backend::Auto:
      return cudaUsable(&reason) ? Backend::Cuda : Backend::Cpu;
    case Backend::Cpu:
      return Backend::Cpu;
    case Backend::Cuda:
      if (!cudaUsable(&reason)) throw BackendError("the CUDA backend cannot run: " + reason);
      return Backend::Cuda;
  }
  return Backend::Cpu;
}

bool needsOwnBvh(Backend backend, CpuEngine cpuEngine) {
  return backend == Backend::Cuda || cpuEngine != CpuEngine::Embree;
}

std::unique_ptr<Renderer> makeRenderer(Backend backend, CpuEngine cpuEngine) {
  switch (backend) {
    case Backend::Auto:
    case Backend::Cpu:
      return std::make_unique<CpuRenderer>(cpuEngine);
    case Backend::Cuda:
#if defined(CANDELA_HAS_CUDA)
      return std::make_unique<CudaRenderer>();
#else
      break;
#endif
  }
  std::string reason;
  cudaUsable(&reason);
  throw BackendError("the CUDA backend cannot run: " + reason);
}

}  // namespace candela
