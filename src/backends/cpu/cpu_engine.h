// Which ray engine the CPU backend traces with: Embree (Intel's kernels, chosen at run time for
// the CPU's widest SIMD) or candela's own 4-wide BVH, the one the CUDA backend runs.
#pragma once

#include <cstdint>
#include <string>

#include "backends/cpu/sphere_blocks.h"

namespace candela {

enum class CpuEngine { Auto, Embree, Bvh };

// "auto", "embree" or "bvh".
const char* cpuEngineName(CpuEngine engine);

// "auto", "embree" or "bvh" (any case); false for anything else.
bool cpuEngineFromName(const std::string& name, CpuEngine* engine);

// Whether this build has the Embree engine (CANDELA_EMBREE).
bool embreeAvailable();

// The version of the Embree it was built with ("3.13.5"); "" without Embree.
const char* embreeVersion();

// Auto picks Embree for scenes of at least kEmbreeFromTriangles triangles, and for smaller scenes
// of at most kSphereBlocksUpTo spheres (backends/cpu/sphere_blocks.h), which the Embree engine
// tests in blocks (of 4 then): there, on one core, the default room (nine spheres, a 4,320-triangle
// knot) took 0.86x the own BVH's CPU time, the same room without the knot 0.67x, 32 spheres 0.81x,
// the Cornell box (32 triangles) 0.95x and scenes of 12k to 8.5M triangles 0.5-0.83x. With more
// spheres the Embree engine puts them in a BVH of their own, traced before Embree's, and the own
// BVH, one traversal for all, is as fast or faster (docs/performance.md).
constexpr uint64_t kEmbreeFromTriangles = 10000;

// Resolves Auto to Embree where the build has it and the scene's `triangles` and `spheres` (sphere
// lights included) favour it as above, else to the own BVH; `flatBvh` (--no-bvh, which asks for
// the own engine's one-level tree) resolves Auto to the own BVH. Throws BackendError for Embree
// in a build without it, or with flatBvh.
CpuEngine resolveCpuEngine(CpuEngine requested, bool flatBvh, uint64_t triangles,
                           uint64_t spheres);

}  // namespace candela
