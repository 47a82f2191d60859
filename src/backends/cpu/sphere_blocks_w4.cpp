// The sphere-block tests 4 spheres wide (backends/cpu/sphere_blocks_kernel.h), in SSE2, which every
// x86-64 CPU has.
#if defined(__x86_64__)
#include "backends/cpu/sphere_blocks_kernel.h"

CANDELA_SPHERE_BLOCK_TESTS(4)
#endif
