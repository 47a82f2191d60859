// isFiniteRay (geometry/bvh_traverse.h) without a branch per component, for the CPU tracer, which
// asks it before every query: the portable form takes six comparisons, each with its branch.
#pragma once

#include <cstdint>
#include <cstring>

#include "geometry/ray.h"

namespace candela {

// Whether every component of the ray's origin and direction is finite, as isFiniteRay answers.
// A float is finite where its exponent bits are not all ones, so one added to the exponent field
// carries into the sign bit only for infinities and NaNs. The words are read one float at a time:
// the ray was just stored that way, and a wider load across those stores waits for them to
// retire instead of taking their values from the store buffer (a store-forwarding stall that cost
// more than the comparisons).
inline bool isFiniteRayCpu(const Ray& ray) {
  const float c[6] = {ray.origin.x,    ray.origin.y,    ray.origin.z,
                      ray.direction.x, ray.direction.y, ray.direction.z};
  uint32_t carried = 0;
  for (const float v : c) {
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    carried |= (bits & 0x7f800000u) + 0x00800000u;
  }
  return (carried & 0x80000000u) == 0;
}

}  // namespace candela
