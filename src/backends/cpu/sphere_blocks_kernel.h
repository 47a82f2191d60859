// The sphere-block tests of backends/cpu/sphere_blocks.h, written once over W lanes (GCC/Clang
// vector extensions) and compiled once per width, each in its own file with its instruction set:
// sphere_blocks_w4.cpp (SSE2) and _w8.cpp (AVX2). Only those files include it.
//
// Everything here has internal linkage and calls no inline function of another header but
// simd_lanes.h's, internal too, so no AVX code can stand in, at link time, for a function other
// files expect to run anywhere.
#pragma once

#include <immintrin.h>

#include <cstdint>

#include "backends/cpu/simd_lanes.h"
#include "backends/cpu/sphere_blocks.h"

namespace candela {
namespace {

template <int W>
inline typename Lanes<W>::F squareRoot(typename Lanes<W>::F x) {
  if constexpr (W == 4) return _mm_sqrt_ps(x);
  if constexpr (W == 8) return _mm256_sqrt_ps(x);
}

template <int W>
struct RayLanes {
  typename Lanes<W>::F ox, oy, oz, dx, dy, dz, a;
  explicit RayLanes(const Ray& r)
      : ox(splat<W>(r.origin.x)),
        oy(splat<W>(r.origin.y)),
        oz(splat<W>(r.origin.z)),
        dx(splat<W>(r.direction.x)),
        dy(splat<W>(r.direction.y)),
        dz(splat<W>(r.direction.z)),
        // lengthSquared(direction), in its order.
        a(splat<W>(r.direction.x * r.direction.x + r.direction.y * r.direction.y +
                   r.direction.z * r.direction.z)) {}
};

// intersectSphere (geometry/sphere_intersect.h) on the W spheres of block `block`, lane by lane,
// with its operations in its order: returns the hit distances, and in *hit all ones in the lanes
// that hit for t in (0, tMax). Returns false, *hit untouched, when a first cheap look, before any
// division or square root, shows that no lane can hit.
template <int W>
inline bool blockHits(const SphereBlocksView& b, uint32_t block, const RayLanes<W>& r, float tMax,
                      typename Lanes<W>::F* distances, typename Lanes<W>::I* hit) {
  using F = typename Lanes<W>::F;
  using I = typename Lanes<W>::I;
  const size_t o = size_t(block) * W;
  const F ocx = r.ox - load<W>(b.centerX + o);
  const F ocy = r.oy - load<W>(b.centerY + o);
  const F ocz = r.oz - load<W>(b.centerZ + o);
  const F halfB = ocx * r.dx + ocy * r.dy + ocz * r.dz;
  const F ocSquared = ocx * ocx + ocy * ocy + ocz * ocz;
  const F radiusSquared = load<W>(b.radiusSquared + o);
  const F c = ocSquared - radiusSquared;
  // From outside, moving away or with the near root beyond tMax: a miss (intersectSphere's test).
  const I beyond = (c > 0.0f) & (c >= tMax * (-2.0f * halfB));
  // Passing clearly wide: a |perp|^2 = a |oc|^2 - halfB^2 exceeds a r^2 by more than the rounding
  // of either side (both err by a few ulp of a (|oc|^2 + r^2)), so the exact test below misses.
  const F aPerpSquared = r.a * ocSquared - halfB * halfB;
  const F margin = 1e-6f * r.a * (ocSquared + radiusSquared);
  const I wide = (aPerpSquared - r.a * radiusSquared) > margin;
  if (laneBits<W>(beyond | wide) == (1u << W) - 1u) return false;

  const F radius = load<W>(b.radius + o);
  const F k = halfB / r.a;
  const F px = ocx - k * r.dx;
  const F py = ocy - k * r.dy;
  const F pz = ocz - k * r.dz;
  const F perpLength = squareRoot<W>(px * px + py * py + pz * pz);
  const I passesBy = perpLength > radius;
  const F discriminant = r.a * (radius - perpLength) * (radius + perpLength);
  const I signBit = I{} + int32_t(0x80000000u);
  const F signedRoot = F((I(squareRoot<W>(discriminant)) & ~signBit) | (I(halfB) & signBit));
  const F q = -(halfB + signedRoot);
  const F t0 = q / r.a;
  const F t1 = c / q;
  const I swapped = t0 > t1;
  const F nearT = swapped ? t1 : t0;
  const F farT = swapped ? t0 : t1;
  const I nearOk = (nearT > 0.0f) & (nearT < tMax);
  const I farOk = (farT > 0.0f) & (farT < tMax);
  *hit = ~(beyond | passesBy) & (nearOk | farOk);
  *distances = nearOk ? nearT : farT;
  return true;
}

template <int W>
bool closestSphereInLanes(const SphereBlocksView& blocks, const Ray& ray, float tMax, float* t,
                          uint32_t* prim) {
  using F = typename Lanes<W>::F;
  using I = typename Lanes<W>::I;
  // Every block is tested against the same tMax, so blocks do not wait on each other's results;
  // each lane keeps its nearest hit (the earliest block's on a tie), and the lanes are compared
  // at the end. A smaller tMax would only have turned hits beyond the nearest into misses.
  const RayLanes<W> lanes(ray);
  F nearest = splat<W>(tMax);
  I nearestBlock = I{};
  for (uint32_t block = 0; block < blocks.blockCount; ++block) {
    F distances;
    I hit;
    if (!blockHits<W>(blocks, block, lanes, tMax, &distances, &hit)) continue;
    const I nearer = (distances < nearest) & hit;
    nearest = nearer ? distances : nearest;
    nearestBlock = nearer ? I{} + int32_t(block) : nearestBlock;
  }
  // The nearest lane, the lowest sphere index on a tie: reduced across the lanes rather than
  // looked for lane by lane, whose branches a CPU mispredicts from ray to ray (a third of this
  // test's time in the sphere-walled rooms, where a ray's line meets two or three walls).
  const F closestT = minAcrossLanes<W>(nearest);
  if (!(closestT[0] < tMax)) return false;
  const I index = nearestBlock * W + laneIndices<W>();
  const I tied = (nearest == closestT) & (nearest < tMax);
  *t = closestT[0];
  *prim = uint32_t(minAcrossLanes<W>(tied ? index : I{} + INT32_MAX)[0]);
  return true;
}

template <int W>
bool anySphereInLanes(const SphereBlocksView& blocks, const Ray& ray, uint32_t skipPrim) {
  const RayLanes<W> lanes(ray);
  for (uint32_t block = 0; block < blocks.blockCount; ++block) {
    typename Lanes<W>::F distances;
    typename Lanes<W>::I hit;
    if (!blockHits<W>(blocks, block, lanes, ray.tMax, &distances, &hit)) continue;
    if (withoutSkippedLane<W>(laneBits<W>(hit), skipPrim, block) != 0) return true;
  }
  return false;
}

}  // namespace
}  // namespace candela

// Defines closestSphereW<W> and anySphereW<W> (backends/cpu/sphere_blocks.h) over the kernel above.
#define CANDELA_SPHERE_BLOCK_TESTS(W)                                                          \
  namespace candela {                                                                          \
  bool closestSphereW##W(const SphereBlocksView& blocks, const Ray& ray, float tMax, float* t, \
                         uint32_t* prim) {                                                     \
    return closestSphereInLanes<W>(blocks, ray, tMax, t, prim);                                \
  }                                                                                            \
  bool anySphereW##W(const SphereBlocksView& blocks, const Ray& ray, uint32_t skipPrim) {      \
    return anySphereInLanes<W>(blocks, ray, skipPrim);                                         \
  }                                                                                            \
  }
