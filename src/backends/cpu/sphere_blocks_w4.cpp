// The sphere-block tests 4 spheres wide (backends/cpu/sphere_blocks_kernel.h), in SSE2, which every
// x86-64 CPU has.
#if defined(__x86_64__)
#include "backends/cpu/sphere_blocks_kernel.h"

namespace candela {

bool closestSphereW4(const SphereBlocksView& blocks, const Ray& ray, float tMax, float* t,
                     uint32_t* prim) {
  return closestSphereInLanes<4>(blocks, ray, tMax, t, prim);
}

bool anySphereW4(const SphereBlocksView& blocks, const Ray& ray, uint32_t skipPrim) {
  return anySphereInLanes<4>(blocks, ray, skipPrim);
}

}  // namespace candela

#endif
