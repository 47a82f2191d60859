// The triangle-block tests of backends/cpu/triangle_blocks.h, written once over W lanes (GCC/Clang
// vector extensions) and compiled for AVX2 and FMA in triangle_blocks_w8.cpp, the only file to
// include it.
//
// Everything here has internal linkage and calls no inline function of another header but
// simd_lanes.h's, internal too, so no AVX code can stand in, at link time, for a function other
// files expect to run anywhere.
#pragma once

#include <immintrin.h>

#include <cstdint>

#include "backends/cpu/simd_lanes.h"
#include "backends/cpu/triangle_blocks.h"

namespace candela {
namespace {

template <int W>
struct RayLanes {
  typename Lanes<W>::F ox, oy, oz, dx, dy, dz;
  explicit RayLanes(const Ray& r)
      : ox(splat<W>(r.origin.x)),
        oy(splat<W>(r.origin.y)),
        oz(splat<W>(r.origin.z)),
        dx(splat<W>(r.direction.x)),
        dy(splat<W>(r.direction.y)),
        dz(splat<W>(r.direction.z)) {}
};

// One block's test before any division: with C = p0 - o and R = d x C, the hit's barycentrics and
// distance times det = n.d are U = R.b, V = R.a and T = n.C; here made positive by det's sign
// (Embree's Moeller-Trumbore form). Returns the lanes that hit for t in (0, tMax), all ones.
template <int W>
struct BlockTest {
  typename Lanes<W>::F u, v, t, absDet;  // U, V, T with det's sign taken off, and |det|
  typename Lanes<W>::I hit;
};

template <int W>
inline BlockTest<W> testBlock(const TriangleBlocksView& b, uint32_t block, const RayLanes<W>& r,
                              typename Lanes<W>::F tMax) {
  using F = typename Lanes<W>::F;
  using I = typename Lanes<W>::I;
  const float* lanes = b.data + size_t(block) * 12 * W;
  const auto at = [&](int k) { return load<W>(lanes + k * W); };
  const F cx = at(0) - r.ox, cy = at(1) - r.oy, cz = at(2) - r.oz;
  const F rx = r.dy * cz - r.dz * cy;
  const F ry = r.dz * cx - r.dx * cz;
  const F rz = r.dx * cy - r.dy * cx;
  const F nx = at(9), ny = at(10), nz = at(11);
  const F det = nx * r.dx + ny * r.dy + nz * r.dz;
  const I signBit = I{} + int32_t(0x80000000u);
  const I detSign = I(det) & signBit;
  BlockTest<W> test;
  test.u = F(I(rx * at(6) + ry * at(7) + rz * at(8)) ^ detSign);
  test.v = F(I(rx * at(3) + ry * at(4) + rz * at(5)) ^ detSign);
  test.t = F(I(nx * cx + ny * cy + nz * cz) ^ detSign);
  test.absDet = F(I(det) & ~signBit);
  test.hit = (test.absDet > 0.0f) & (test.u >= 0.0f) & (test.v >= 0.0f) &
             (test.u + test.v <= test.absDet) & (test.t > 0.0f) & (test.t < tMax * test.absDet);
  return test;
}

template <int W>
bool closestTriangleInLanes(const TriangleBlocksView& blocks, const Ray& ray, float tMax, float* t,
                            uint32_t* triangle, float* b1, float* b2) {
  using F = typename Lanes<W>::F;
  using I = typename Lanes<W>::I;
  // Each lane keeps its nearest hit (the earliest block's on a tie) with what its barycentrics
  // need; the lanes are compared at the end.
  const RayLanes<W> lanes(ray);
  const F far = splat<W>(tMax);
  F nearest = far, nearestU = F{}, nearestV = F{}, nearestDet = F{};
  I nearestBlock = I{};
  for (uint32_t block = 0; block < blocks.blockCount; ++block) {
    const BlockTest<W> test = testBlock<W>(blocks, block, lanes, far);
    const F distances = test.t / test.absDet;
    const I nearer = (distances < nearest) & test.hit;
    nearest = nearer ? distances : nearest;
    nearestU = nearer ? test.u : nearestU;
    nearestV = nearer ? test.v : nearestV;
    nearestDet = nearer ? test.absDet : nearestDet;
    nearestBlock = nearer ? I{} + int32_t(block) : nearestBlock;
  }
  // The nearest lane, the lowest triangle index on a tie.
  bool found = false;
  uint32_t best = 0;
  for (uint32_t bits = laneBits<W>(nearest < far); bits != 0; bits &= bits - 1) {
    const uint32_t lane = uint32_t(__builtin_ctz(bits));
    const uint32_t index = uint32_t(nearestBlock[lane]) * W + lane;
    if (found && !(nearest[lane] < *t || (nearest[lane] == *t && index < *triangle))) continue;
    *t = nearest[lane];
    *triangle = index;
    best = lane;
    found = true;
  }
  if (found) {
    *b1 = nearestU[best] / nearestDet[best];
    *b2 = nearestV[best] / nearestDet[best];
  }
  return found;
}

template <int W>
bool anyTriangleInLanes(const TriangleBlocksView& blocks, const Ray& ray, uint32_t skipTriangle) {
  const RayLanes<W> lanes(ray);
  const typename Lanes<W>::F far = splat<W>(ray.tMax);
  for (uint32_t block = 0; block < blocks.blockCount; ++block) {
    const uint32_t hitBits = laneBits<W>(testBlock<W>(blocks, block, lanes, far).hit);
    if (withoutSkippedLane<W>(hitBits, skipTriangle, block) != 0) return true;
  }
  return false;
}

}  // namespace
}  // namespace candela

// Defines closestTriangleW<W> and anyTriangleW<W> (backends/cpu/triangle_blocks.h) over the
// kernel above.
#define CANDELA_TRIANGLE_BLOCK_TESTS(W)                                                            \
  namespace candela {                                                                              \
  bool closestTriangleW##W(const TriangleBlocksView& blocks, const Ray& ray, float tMax, float* t, \
                           uint32_t* triangle, float* b1, float* b2) {                             \
    return closestTriangleInLanes<W>(blocks, ray, tMax, t, triangle, b1, b2);                      \
  }                                                                                                \
  bool anyTriangleW##W(const TriangleBlocksView& blocks, const Ray& ray, uint32_t skipTriangle) {  \
    return anyTriangleInLanes<W>(blocks, ray, skipTriangle);                                       \
  }                                                                                                \
  }
