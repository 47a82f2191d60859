// Counter-based random numbers: each value is a pure function of
// (seed, pixel, sample index, dimension), so any thread, tile order, backend or cluster node
// draws exactly the same stream for a given sample.
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

// The random stream of one (seed, pixel, sample). `next()` walks the dimensions in order;
// the integrator consumes them in a fixed order per bounce, so streams never depend on timing.
struct SampleStream {
  uint64_t key = 0;
  uint32_t dimension = 0;

  CANDELA_HDI SampleStream(uint64_t seed, uint64_t pixelIndex, uint64_t sampleIndex) {
    key = mix64(mix64(mix64(seed ^ 0x6a09e667f3bcc909ull) ^ pixelIndex) ^ sampleIndex);
  }

  CANDELA_HDI float next() { return toUnitFloat(mix64(key + 0x9e3779b97f4a7c15ull * ++dimension)); }
};

}  // namespace candela
