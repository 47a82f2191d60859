// isFiniteRay (geometry/bvh_traverse.h) without a branch per component, for the CPU tracer, which
// asks it before every query: the portable form takes six comparisons, each with its branch.
#pragma once

#include <cstdint>
#include <cstring>
#include <initializer_list>

#include "geometry/ray.h"

namespace candela {

// v's exponent field plus one: bit 31 is set only where v is an infinity or a NaN (exponent bits
// all ones), whatever v's sign.
inline uint32_t exponentCarry(float v) {
  uint32_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  return (bits & 0x7f800000u) + 0x00800000u;
}

// Whether every component of the ray's origin and direction is finite, as isFiniteRay answers.
// The floats are read one at a time, as the ray was just stored: a wider load across those
// stores cannot take their values from the store buffer and waits for them (a store-forwarding
// stall that cost more than the check). An empty asm statement keeps each word in a register of
// its own, so the compiler does not merge the six loads into vector loads that meet it again.
inline bool isFiniteRayCpu(const Ray& ray) {
  uint32_t carried = 0;
  for (const float v : {ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y,
                        ray.direction.z}) {
    uint32_t word = exponentCarry(v);
    asm("" : "+r"(word));
    carried |= word;
  }
  return (carried & 0x80000000u) == 0;
}

}  // namespace candela
