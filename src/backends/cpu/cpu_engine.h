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

// Resolves Auto to Embree where the build has it, else the own BVH; `flatBvh` (--no-bvh, which
// asks for the own engine's one-level tree) resolves Auto to the own BVH. Throws BackendError
// for Embree in a build without it, or with flatBvh.
CpuEngine resolveCpuEngine(CpuEngine requested, bool flatBvh);

}  // namespace candela
