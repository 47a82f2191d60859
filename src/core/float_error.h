// Floating-point error bounds (pbrt-v4, section 6.8): a hit point is known to lie in a small box
// around its computed value, so secondary rays start just outside that box along the normal.
// This replaces a scene-scale epsilon: the offset scales with the coordinates themselves.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/vec3.h"

namespace candela {

constexpr float kMachineEpsilon = 0x1p-24f;  // half an ulp of 1.0f

// Bound on the relative error of n chained float operations.
CANDELA_HDI constexpr float gammaBound(int n) { return (n * kMachineEpsilon) / (1 - n * kMachineEpsilon); }

CANDELA_HDI uint32_t floatToBits(float f) {
#if defined(__CUDA_ARCH__)
  return __float_as_uint(f);
#else
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
#endif
}

CANDELA_HDI float bitsToFloat(uint32_t u) {
#if defined(__CUDA_ARCH__)
  return __uint_as_float(u);
#else
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
#endif
}

// The next representable float above / below v, by stepping its bit pattern (IEEE floats of one
// sign are ordered like their bits): what nextafterf does, without a library call per ray.
CANDELA_HDI float nextFloatUp(float v) {
  if (v == INFINITY) return v;  // a comparison, not isinf: compiles alike on host and device
  if (v == -0.0f) v = 0.0f;
  const uint32_t bits = floatToBits(v);
  return bitsToFloat(v >= 0.0f ? bits + 1 : bits - 1);
}

CANDELA_HDI float nextFloatDown(float v) {
  if (v == -INFINITY) return v;
  if (v == 0.0f) v = -0.0f;
  const uint32_t bits = floatToBits(v);
  return bitsToFloat(v > 0.0f ? bits - 1 : bits + 1);
}

// v moved one float further in the direction of `offset`'s sign (not at all where it is zero).
CANDELA_HDI_ALWAYS float stepAwayBy(float v, float offset) {
  return offset > 0.0f ? nextFloatUp(v) : offset < 0.0f ? nextFloatDown(v) : v;
}

// Origin for a ray leaving point p (absolute error bound `error` per axis) in direction w,
// on the side of geometric normal n that w points to.
CANDELA_HDI_ALWAYS Vec3 offsetRayOrigin(const Vec3& p, const Vec3& error, const Vec3& n, const Vec3& w) {
  const float d = dot(abs(n), error);
  Vec3 offset = n * d;
  if (dot(w, n) < 0.0f) offset = -offset;
  const Vec3 po = p + offset;
  // Rounded away from p so the offset is never lost to rounding; component by component in
  // registers (a loop over po[i] kept po in memory, and the Vec3 returned was then read back
  // 8 bytes at a time across its 4-byte stores: a store-forwarding stall on every ray spawned).
  return Vec3(stepAwayBy(po.x, offset.x), stepAwayBy(po.y, offset.y), stepAwayBy(po.z, offset.z));
}

}  // namespace candela
