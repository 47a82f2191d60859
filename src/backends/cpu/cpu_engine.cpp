#include "backends/cpu/cpu_engine.h"

#include <cctype>
#include <cstring>

#include "backends/backend_error.h"

#if defined(CANDELA_HAS_EMBREE)
#include <embree3/rtcore_config.h>
#endif

namespace candela {

const char* cpuEngineName(CpuEngine engine) {
  switch (engine) {
    case CpuEngine::Auto:
      return "auto";
    case CpuEngine::Embree:
      return "embree";
    case CpuEngine::Bvh:
      return "bvh";
  }
  return "?";
}

bool cpuEngineFromName(const std::string& name, CpuEngine* engine) {
  std::string lower;
  for (char c : name) lower += char(std::tolower((unsigned char)c));
  for (CpuEngine e : {CpuEngine::Auto, CpuEngine::Embree, CpuEngine::Bvh}) {
    if (lower == cpuEngineName(e)) {
      *engine = e;
      return true;
    }
  }
  return false;
}

bool embreeAvailable() {
#if defined(CANDELA_HAS_EMBREE)
  return true;
#else
  return false;
#endif
}

const char* embreeVersion() {
#if defined(CANDELA_HAS_EMBREE)
  return RTC_VERSION_STRING;
#else
  return "";
#endif
}

CpuEngine resolveCpuEngine(CpuEngine requested, bool flatBvh, uint64_t triangles,
                           uint64_t spheres) {
  if (requested == CpuEngine::Auto) {
    const bool favoured = triangles >= kEmbreeFromTriangles ||
                          (triangles + spheres > 0 && spheres <= kSphereBlocksUpTo);
    return embreeAvailable() && !flatBvh && favoured ? CpuEngine::Embree : CpuEngine::Bvh;
  }
  if (requested == CpuEngine::Embree) {
    if (!embreeAvailable())
      throw BackendError(
          "the embree CPU engine is not in this build (install libembree-dev and configure with "
          "-DCANDELA_EMBREE=ON)");
    if (flatBvh)
      throw BackendError(
          "--no-bvh tests every primitive with candela's own engine; it cannot be "
          "combined with the embree CPU engine");
  }
  return requested;
}

}  // namespace candela
