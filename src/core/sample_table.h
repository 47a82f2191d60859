// The random numbers of a packet of one pixel's samples, computed together: up to kLanes
// consecutive samples, one SIMD lane each. A sample's SampleStream (core/sobol_sampler.h) that
// has a table reads its first kMaxDimensions dimensions from here, bit for bit what it would
// compute alone. The first sample to ask for a dimension has `fill` compute it for every lane,
// as one or two numbers (next1D's or next2D's); a sample that asks for it the other way computes
// its own. The CPU backend fills tables with SIMD code (backends/cpu/sample_table_fill.h; its
// gain is in docs/performance.md); the GPU has none.
#pragma once

#include <cstdint>

#include "core/device.h"

namespace candela {

struct SampleTable {
  static constexpr uint32_t kLanes = 16;
  static constexpr uint32_t kMaxDimensions = 48;
  // Fewer samples than this draw their own numbers: a fill computes a vector of 8 lanes
  // whatever their count, and for fewer it cost more than it saved (docs/performance.md).
  static constexpr uint32_t kMinLanes = 8;
  enum Kind : uint8_t { kEmpty, kOneD, kTwoD };

  // Computes entry `entry` (dimension entry + 1) for every lane, as next2D's pair where twoD,
  // else next1D's number, and sets kind[entry].
  using Fill = void (*)(SampleTable* table, uint32_t entry, bool twoD);

  Fill fill = nullptr;
  uint64_t pixelKey = 0;  // samplePixelKey(seed, pixel)
  uint32_t firstSample = 0, lanes = 0, spp = 1;
  Kind kind[kMaxDimensions] = {};
  alignas(32) float a[kMaxDimensions][kLanes];  // next1D's number, or next2D's first
  alignas(32) float b[kMaxDimensions][kLanes];  // next2D's second

  // Empties the table for samples [first, first + count) of the pixel keyed `key`.
  CANDELA_HDI void start(uint64_t key, uint32_t first, uint32_t count, uint32_t samplesPerPixel) {
    pixelKey = key;
    firstSample = first;
    lanes = count;
    spp = samplesPerPixel;
    for (uint32_t d = 0; d < kMaxDimensions; ++d) kind[d] = kEmpty;
  }

  // The table, started for those samples, where there are enough of them for it to pay (at least
  // kMinLanes); else null, and the samples draw their own numbers.
  CANDELA_HDI SampleTable* serve(uint64_t key, uint32_t first, uint32_t count,
                                 uint32_t samplesPerPixel) {
    if (count < kMinLanes) return nullptr;
    start(key, first, count, samplesPerPixel);
    return this;
  }
};

}  // namespace candela
