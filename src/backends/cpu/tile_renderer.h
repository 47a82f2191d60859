// The CPU backend's render loop (backends/cpu/render_tiles.h) compiled for more than one
// instruction set, and the choice among them at run time, as Embree chooses its kernels.
//
// The integrator is scalar code, but on a CPU with AVX-512 its build for x86-64-v4 renders 4-13%
// faster (docs/performance.md; a build for AVX2 and FMA alone, x86-64-v3, gained 1%), while the
// rest of candela stays plain x86-64 and runs anywhere. The two copies
// render the same image up to rounding: the x86-64-v4 one fuses multiply-adds, as nvcc does for
// the GPU. Each runs the same on any thread count, so one machine's images stay reproducible.
//
// Each copy's inline functions (the integrator's, the standard library's, oneTBB's) are private
// to its file (-fno-weak), so no AVX-512 code can stand in, at link time, for a function that
// other files call on any CPU: tests/check_isa_object.py holds the x86-64-v4 file to exporting
// its entry point alone.
#pragma once

#include "backends/render_options.h"
#include "geometry/bvh_tracer.h"
#include "render/render_result.h"
#include "render/scene_view.h"

namespace candela {

struct EmbreeTracer;

struct TileRenderer {
  const char* isa;  // "x86-64" or "x86-64-v4"
  RenderResult (*withBvh)(const SceneView&, const BvhTracer&, const RenderOptions&);
  // Null in a build without Embree.
  RenderResult (*withEmbree)(const SceneView&, const EmbreeTracer&, const RenderOptions&);
};

// The loop for any CPU of the build's target (on x86-64: SSE2).
TileRenderer baselineTileRenderer();

#if defined(CANDELA_X86_64_V4_LOOP)
// The loop for x86-64-v4 (AVX-512 F, BW, CD, DQ and VL), to be run only where the CPU has it.
// Built on x86-64 by GCC (CMakeLists.txt: Clang has no -fno-weak).
TileRenderer x86_64V4TileRenderer();
#endif

// The loop named `isa` ("x86-64" or "x86-64-v4"); false when this build or this CPU has none by
// that name.
bool tileRendererByName(const char* isa, TileRenderer* renderer);

// The widest loop the CPU runs; the environment variable CANDELA_CPU_ISA, when set, names one
// instead ("x86-64" or "x86-64-v4"), for measurements and tests. Throws BackendError when it
// names another, or one the CPU cannot run.
TileRenderer tileRenderer();

}  // namespace candela
