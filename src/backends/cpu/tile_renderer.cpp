#include "backends/cpu/tile_renderer.h"

#include <cstdlib>
#include <cstring>
#include <string>

#include "backends/backend_error.h"

namespace candela {

namespace {

bool cpuRunsX86_64V4() {
#if defined(CANDELA_X86_64_V4_LOOP)
  // libgcc's check reads CPUID and, through XGETBV, whether the OS saves the AVX-512 registers.
  return __builtin_cpu_supports("x86-64-v4");
#else
  return false;
#endif
}

}  // namespace

bool tileRendererByName(const char* isa, TileRenderer* renderer) {
#if defined(CANDELA_X86_64_V4_LOOP)
  if (std::strcmp(isa, "x86-64-v4") == 0) {
    if (!cpuRunsX86_64V4()) return false;
    *renderer = x86_64V4TileRenderer();
    return true;
  }
#endif
  const TileRenderer baseline = baselineTileRenderer();
  if (std::strcmp(isa, baseline.isa) != 0) return false;
  *renderer = baseline;
  return true;
}

TileRenderer tileRenderer() {
  TileRenderer renderer = baselineTileRenderer();
  if (const char* named = std::getenv("CANDELA_CPU_ISA"); named && *named) {
    if (!tileRendererByName(named, &renderer))
      throw BackendError(std::string("CANDELA_CPU_ISA=") + named + ": expected " + renderer.isa +
                         (cpuRunsX86_64V4() ? " or x86-64-v4" : "") +
                         ", the instruction sets this build has that this CPU runs");
    return renderer;
  }
  tileRendererByName("x86-64-v4", &renderer);  // the widest, where the CPU runs it
  return renderer;
}

}  // namespace candela
