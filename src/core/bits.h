// Bit scanning shared by host and device code.
#pragma once

#include <cstdint>

#include "core/device.h"

namespace candela {

// Index of the lowest set bit of v; v must not be 0.
CANDELA_HDI int lowestSetBit(uint32_t v) {
#if defined(__CUDA_ARCH__)
  return __ffs(v) - 1;
#else
  return __builtin_ctz(v);
#endif
}

// Index of the highest set bit of v; v must not be 0.
CANDELA_HDI int highestSetBit(uint32_t v) {
#if defined(__CUDA_ARCH__)
  return 31 - __clz(v);
#else
  return 31 - __builtin_clz(v);
#endif
}

}  // namespace candela
