// The sphere-block tests 8 spheres wide (backends/cpu/sphere_blocks_kernel.h), compiled for AVX2;
// called only where the CPU has it (widestSphereBlock).
#if defined(__x86_64__)
#include "backends/cpu/sphere_blocks_kernel.h"

CANDELA_SPHERE_BLOCK_TESTS(8)
#endif
