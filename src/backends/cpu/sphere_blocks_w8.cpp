// The sphere-block tests 8 spheres wide (backends/cpu/sphere_blocks_kernel.h), compiled for AVX2;
// called only where the CPU has it (widestSphereBlock).
#if defined(__x86_64__)
#include "backends/cpu/sphere_blocks_kernel.h"

namespace candela {

bool closestSphereW8(const SphereBlocksView& blocks, const Ray& ray, float tMax, float* t,
                     uint32_t* prim) {
  return closestSphereInLanes<8>(blocks, ray, tMax, t, prim);
}

bool anySphereW8(const SphereBlocksView& blocks, const Ray& ray, uint32_t skipPrim) {
  return anySphereInLanes<8>(blocks, ray, skipPrim);
}

}  // namespace candela

#endif
