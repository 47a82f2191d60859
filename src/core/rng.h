// Counter-based hashing: the building block of the sampler (core/sobol_sampler.h), which makes
// every random number a pure function of (seed, pixel, sample index, dimension).
#pragma once

#include <cstdint>

#include "core/constants.h"
#include "core/device.h"

namespace candela {

// SplitMix64's finaliser: a bijective 64-bit mixer with full avalanche.
CANDELA_HDI uint64_t mix64(uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// Maps the top 24 bits of a hash to a float in [0, 1); never returns 1.
CANDELA_HDI float toUnitFloat(uint64_t bits) {
  return static_cast<float>(static_cast<uint32_t>(bits >> 40)) * 0x1p-24f;
}

}  // namespace candela
