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

// Auto picks Embree for scenes of at least kEmbreeFromTriangles triangles, and for smaller scenes
// with triangles and at most kEmbreeUpToSpheres spheres. With Embree the spheres stay in an own
// BVH traced first, so a ray pays two traversals: the default room of nine spheres (six of them
// its walls) and a 4,320-triangle knot took 1.25x the CPU time with Embree, while the sky scene
// (four spheres, the same knot) took 0.85x, the Cornell box (32 triangles) 0.95x and scenes of 12k
// to 8.5M triangles 0.5-0.83x (docs/performance.md).
constexpr uint64_t kEmbreeFromTriangles = 10000;
constexpr uint64_t kEmbreeUpToSpheres = 4;

// Resolves Auto to Embree where the build has it and the scene's `triangles` and `spheres` (sphere
// lights included) favour it as above, else to the own BVH; `flatBvh` (--no-bvh, which asks for
// the own engine's one-level tree) resolves Auto to the own BVH. Throws BackendError for Embree
// in a build without it, or with flatBvh.
CpuEngine resolveCpuEngine(CpuEngine requested, bool flatBvh, uint64_t triangles,
                           uint64_t spheres);

}  // namespace candela
