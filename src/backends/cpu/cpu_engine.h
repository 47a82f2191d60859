// Which ray engine the CPU backend traces with: Embree (Intel's kernels, chosen at run time for
// the CPU's widest SIMD) or candela's own 4-wide BVH, the one the CUDA backend runs.
#pragma once

#include <string>

namespace candela {

enum class CpuEngine { Auto, Embree, Bvh };

// "auto", "embree" or "bvh".
const char* cpuEngineName(CpuEngine engine);

// "auto", "embree" or "bvh" (any case); false for anything else.
bool cpuEngineFromName(const std::string& name, CpuEngine* engine);

// Whether this build has the Embree engine (CANDELA_EMBREE).
bool embreeAvailable();

// Auto picks Embree for scenes of at least this many triangles. Below it the own BVH was as fast
// or faster where spheres make much of the scene: the default room of huge spheres and a 4,320-
// triangle knot took 1.27x the CPU time with Embree (the spheres stay in an own BVH, and each
// ray pays the call into Embree besides), while scenes of 12k to 8.5M triangles took 0.5-0.83x
// (docs/performance.md).
constexpr uint64_t kEmbreeFromTriangles = 10000;

// Resolves Auto to Embree where the build has it and the scene has at least
// kEmbreeFromTriangles triangles, else to the own BVH; `flatBvh` (--no-bvh, which asks for the own
// engine's one-level tree) resolves Auto to the own BVH. Throws BackendError for Embree in a
// build without it, or with flatBvh.
CpuEngine resolveCpuEngine(CpuEngine requested, bool flatBvh, uint64_t triangles);

}  // namespace candela
