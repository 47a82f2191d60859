#include "backends/backend_report.h"

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "backends/backend_error.h"
#include "backends/cpu/cpu_engine.h"
#include "backends/cpu/tile_renderer.h"
#include "backends/renderer.h"
#include "backends/thread_limit.h"

#if defined(CANDELA_HAS_CUDA)
#include "backends/cuda/cuda_renderer.h"
#endif

namespace candela {
namespace {

// The processor's name as Linux gives it ("model name" in /proc/cpuinfo); "" elsewhere.
std::string cpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const size_t colon = line.find(':');
    if (colon == std::string::npos) break;
    const size_t start = line.find_first_not_of(" \t", colon + 1);
    return start == std::string::npos ? "" : line.substr(start);
  }
  return "";
}

// The widest vector instructions the processor has; Embree picks its kernels for them at run
// time, as candela does its sphere and triangle blocks.
const char* widestSimd() {
#if defined(__x86_64__) || defined(__i386__)
  if (__builtin_cpu_supports("avx512f")) return "AVX-512";
  if (__builtin_cpu_supports("avx2")) return "AVX2";
  if (__builtin_cpu_supports("avx")) return "AVX";
  return "SSE2";
#else
  return "no x86 vector instructions";
#endif
}

// The instruction set the render loop runs in (backends/cpu/tile_renderer.h), or why none does.
std::string renderLoopIsa() {
  try {
    return tileRenderer().isa;
  } catch (const BackendError& e) {
    return e.what();
  }
}

std::string cpuSummary(int threads) {
  const ThreadLimit limit(threads);
  const int used = int(std::min(
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism),
      size_t(tbb::this_task_arena::max_concurrency())));
  const std::string model = cpuModel();
  std::string text = (model.empty() ? std::string("this processor") : model) + ", " +
                     std::to_string(used) + (used == 1 ? " thread, " : " threads, ") +
                     widestSimd() + "; render loop: " + renderLoopIsa() + "; ray engines: ";
  if (embreeAvailable()) text += std::string("Embree ") + embreeVersion() + ", ";
  return text + "candela's own BVH";
}

std::string cudaSummary(bool* usable) {
  std::string reason;
  *usable = cudaUsable(&reason);
  if (!*usable) return "not usable: " + reason;
#if defined(CANDELA_HAS_CUDA)
  return cudaDeviceSummary();
#else
  return "";
#endif
}

}  // namespace

std::vector<BackendReport> reportBackends(int threads) {
  bool cudaReady = false;
  std::string cuda = cudaSummary(&cudaReady);
  const Backend picked = chooseBackend(Backend::Auto);
  return {{backendName(Backend::Cpu), true, cpuSummary(threads), picked == Backend::Cpu},
          {backendName(Backend::Cuda), cudaReady, std::move(cuda), picked == Backend::Cuda}};
}

}  // namespace candela
