// The triangle-block tests 8 triangles wide (backends/cpu/triangle_blocks_kernel.h), compiled for
// AVX2 and FMA; called only where the CPU has both (widestTriangleBlock).
#if defined(__x86_64__)
#include "backends/cpu/triangle_blocks_kernel.h"

CANDELA_TRIANGLE_BLOCK_TESTS(8)
#endif
