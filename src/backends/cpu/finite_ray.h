// isFiniteRay (geometry/bvh_traverse.h) in four SSE comparisons and one branch, for the CPU
// tracer, which asks it before every query: the portable form takes six, each with its branch.
#pragma once

#include <cstring>

#include "core/constants.h"
#include "geometry/bvh_traverse.h"
#include "geometry/ray.h"

#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace candela {

// Whether every component of the ray's origin and direction is finite (NaN fails every
// comparison; infinities exceed the largest float), as isFiniteRay answers.
inline bool isFiniteRayCpu(const Ray& ray) {
#if !defined(__SSE2__)
  return isFiniteRay(ray);
#else
  static_assert(sizeof(Vec3) == 3 * sizeof(float), "Vec3 must be three floats");
  float v[6];
  std::memcpy(v, &ray.origin, sizeof(Vec3));
  std::memcpy(v + 3, &ray.direction, sizeof(Vec3));
  const __m128 magnitude = _mm_castsi128_ps(_mm_set1_epi32(0x7fffffff));
  const __m128 largest = _mm_set1_ps(kInfinity);
  const __m128 low = _mm_and_ps(_mm_loadu_ps(v), magnitude);       // origin, direction.x
  const __m128 high = _mm_and_ps(_mm_loadu_ps(v + 2), magnitude);  // origin.z, direction
  const __m128 finite = _mm_and_ps(_mm_cmple_ps(low, largest), _mm_cmple_ps(high, largest));
  return _mm_movemask_ps(finite) == 0xf;
#endif
}

}  // namespace candela
