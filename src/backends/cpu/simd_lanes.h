// W float or int lanes as GCC/Clang vector extensions, and the few operations on them that the
// block kernels share (backends/cpu/sphere_blocks_kernel.h, triangle_blocks_kernel.h). Only those
// headers include it, each compiled in files of their own instruction set.
//
// Everything here has internal linkage (an unnamed namespace: each file compiles its own copy), so
// no AVX code can stand in, at link time, for a function other files expect to run anywhere.
#pragma once

#include <immintrin.h>

#include <cstdint>

namespace candela {
namespace {

template <int W>
struct Lanes {
  typedef float F __attribute__((vector_size(W * 4)));
  typedef int32_t I __attribute__((vector_size(W * 4)));
  typedef float Unaligned __attribute__((vector_size(W * 4), aligned(4)));
};

// W floats from p, which need no alignment beyond a float's.
template <int W>
inline typename Lanes<W>::F load(const float* p) {
  return *reinterpret_cast<const typename Lanes<W>::Unaligned*>(p);
}

// Bit k set where lane k of `mask` (all ones or all zeros) is set.
template <int W>
inline uint32_t laneBits(typename Lanes<W>::I mask) {
  if constexpr (W == 4) return uint32_t(_mm_movemask_ps(__m128(mask)));
  if constexpr (W == 8) return uint32_t(_mm256_movemask_ps(__m256(mask)));
}

// `hitBits` (laneBits of block `block`) without the lane of primitive `skip`, where that block
// holds it: in bits, not behind a branch, since which block holds it changes from ray to ray.
template <int W>
inline uint32_t withoutSkippedLane(uint32_t hitBits, uint32_t skip, uint32_t block) {
  const uint32_t lane = skip - block * W;
  return hitBits & ~(uint32_t(lane < W) << (lane % W));
}

// 0, 1, ..., W - 1.
template <int W>
inline typename Lanes<W>::I laneIndices() {
  typename Lanes<W>::I v;
  for (int i = 0; i < W; ++i) v[i] = i;
  return v;
}

// The least of v's lanes, in every lane (float or int lanes; of floats, none NaN).
template <int W, typename V>
inline V minAcrossLanes(V v) {
  const auto lesser = [](V a, V b) { return a < b ? a : b; };
  if constexpr (W == 8) {
    v = lesser(v, __builtin_shufflevector(v, v, 4, 5, 6, 7, 0, 1, 2, 3));
    v = lesser(v, __builtin_shufflevector(v, v, 2, 3, 0, 1, 6, 7, 4, 5));
    return lesser(v, __builtin_shufflevector(v, v, 1, 0, 3, 2, 5, 4, 7, 6));
  } else {
    v = lesser(v, __builtin_shufflevector(v, v, 2, 3, 0, 1));
    return lesser(v, __builtin_shufflevector(v, v, 1, 0, 3, 2));
  }
}

// x in every lane, -0 included (adding x to a zero vector would turn -0 into +0).
template <int W>
inline typename Lanes<W>::F splat(float x) {
  typename Lanes<W>::F v;
  for (int i = 0; i < W; ++i) v[i] = x;
  return v;
}

}  // namespace
}  // namespace candela
