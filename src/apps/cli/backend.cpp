// Backend choice and dispatch for the CLI.
#include "apps/cli/backend.h"

#include <cctype>
#include <cstring>
#include <string>

#include "apps/cli/cli_error.h"
#include "backends/cpu/cpu_renderer.h"

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

Backend chooseBackend(Backend requested) {
  switch (requested) {
    case Backend::Auto:
      // The CPU until the CUDA backend can render; then: CUDA when a device is present.
      return Backend::Cpu;
    case Backend::Cpu:
      return Backend::Cpu;
    case Backend::Cuda:
#if defined(CANDELA_HAS_CUDA)
      return Backend::Cuda;
#else
      throw CliError(kExitFailure,
                     "the CUDA backend is not available in this build (configure with "
                     "-DCANDELA_CUDA=ON on a machine with the CUDA toolkit)");
#endif
  }
  return Backend::Cpu;
}

RenderResult renderScene(Backend backend, const SceneData& scene, const RenderControl& control) {
  switch (backend) {
    case Backend::Auto:
    case Backend::Cpu: {
      CpuRenderOptions options;
      options.threads = control.threads;
      options.progress = control.progress;
      options.cancel = control.cancel;
      return renderCpu(scene.view(), options);
    }
    case Backend::Cuda:
      break;  // the CUDA backend's entry point is connected here once it exists
  }
  throw CliError(kExitFailure, std::string("the ") + backendName(backend) +
                                   " backend cannot render from the command line yet");
}

}  // namespace candela::cli
