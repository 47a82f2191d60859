// Axis-aligned bounding boxes: the box type used by the BVH build and the slab test used by
// traversal on every device.
//
// An empty box has lo = +max, hi = -max, so growing it by any point or box just works.
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/float_error.h"

// SSE for the four-box test on x86-64 hosts; never in CUDA device code.
#if !defined(__CUDA_ARCH__) && (defined(__SSE2__) || defined(_M_X64))
#include <immintrin.h>
#define CANDELA_HOST_SSE 1
#else
#define CANDELA_HOST_SSE 0
#endif
#include "core/vec3.h"

namespace candela {

// Per-component min and max written as comparisons: fminf/fmaxf must honour NaN rules that keep
// host compilers from inlining them (each becomes a library call), and the BVH build runs these
// billions of times. A NaN in `b` leaves `a` unchanged, which is what growing a box wants.
CANDELA_HDI Vec3 minByCompare(const Vec3& a, const Vec3& b) {
  return {b.x < a.x ? b.x : a.x, b.y < a.y ? b.y : a.y, b.z < a.z ? b.z : a.z};
}
CANDELA_HDI Vec3 maxByCompare(const Vec3& a, const Vec3& b) {
  return {b.x > a.x ? b.x : a.x, b.y > a.y ? b.y : a.y, b.z > a.z ? b.z : a.z};
}

struct Bounds3 {
  Vec3 lo{kInfinity};
  Vec3 hi{-kInfinity};

  Bounds3() = default;  // implicitly host and device
  CANDELA_HDI Bounds3(const Vec3& lo_, const Vec3& hi_) : lo(lo_), hi(hi_) {}
  CANDELA_HDI explicit Bounds3(const Vec3& p) : lo(p), hi(p) {}

  CANDELA_HDI bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
  CANDELA_HDI void grow(const Vec3& p) {
    lo = minByCompare(lo, p);
    hi = maxByCompare(hi, p);
  }
  CANDELA_HDI void grow(const Bounds3& b) {
    lo = minByCompare(lo, b.lo);
    hi = maxByCompare(hi, b.hi);
  }
  CANDELA_HDI Vec3 extent() const { return empty() ? Vec3(0.0f) : hi - lo; }
  CANDELA_HDI Vec3 centroid() const { return 0.5f * (lo + hi); }
  CANDELA_HDI float surfaceArea() const {
    const Vec3 d = extent();
    return 2.0f * (d.x * d.y + d.y * d.z + d.z * d.x);
  }
  // True when b lies inside this box (boundaries included). An empty b is inside anything.
  CANDELA_HDI bool contains(const Bounds3& b) const {
    return b.empty() || (lo.x <= b.lo.x && lo.y <= b.lo.y && lo.z <= b.lo.z && hi.x >= b.hi.x &&
                         hi.y >= b.hi.y && hi.z >= b.hi.z);
  }
};

CANDELA_HDI Bounds3 unionBounds(Bounds3 a, const Bounds3& b) {
  a.grow(b);
  return a;
}

// A ray prepared for many box tests: reciprocal direction and, per axis, which box face the ray
// enters through (the far one when the direction is negative).
struct RayBoxTester {
  Vec3 origin;
  Vec3 invDir;
  int nearIsHi[3];

  // From the reciprocal direction (an infinity for a zero component is expected and fine).
  CANDELA_HDI RayBoxTester(const Vec3& o, const Vec3& inverseDirection)
      : origin(o), invDir(inverseDirection) {
    for (int i = 0; i < 3; ++i) nearIsHi[i] = invDir[i] < 0.0f;
  }

  // Slab test for t in [0, tMax] against [lo, hi]; on a hit `tEntry` is where the ray enters.
  //
  // Robustness (pbrt-v4, section 6.8.2): the far distance is enlarged by 1 + 2 gamma(3), the bound
  // on the rounding error of both distances, so a ray that truly touches the box never misses.
  // A ray parallel to an axis that starts exactly on a slab plane computes 0 * inf = NaN there;
  // NaN fails every comparison below, so that slab simply constrains nothing, which is right:
  // such a ray lies in the closed slab for all t. A parallel ray outside the slab gets an exit of
  // -inf (or an entry of +inf) and misses, as it should.
  CANDELA_HDI bool hit(const Vec3& lo, const Vec3& hi, float tMax, float* tEntry) const {
    constexpr float kFarScale = 1.0f + 2.0f * gammaBound(3);
    float t0 = 0.0f, t1 = tMax;
    for (int i = 0; i < 3; ++i) {
      const float nearPlane = nearIsHi[i] ? hi[i] : lo[i];
      const float farPlane = nearIsHi[i] ? lo[i] : hi[i];
      const float tNear = (nearPlane - origin[i]) * invDir[i];
      const float tFar = (farPlane - origin[i]) * invDir[i] * kFarScale;
      t0 = tNear > t0 ? tNear : t0;
      t1 = tFar < t1 ? tFar : t1;
    }
    *tEntry = t0;
    return t0 <= t1;
  }

  // The same test against four boxes stored one array per axis (a 4-wide BVH node). Returns a
  // bit mask of the boxes hit and writes each box's entry distance. On x86-64 hosts this is SSE
  // code; elsewhere (CUDA, other CPUs) a scalar loop computing exactly the same values: maxps and
  // minps return their second operand when the first is NaN, as the comparisons below do.
  CANDELA_HDI int hit4(const float lo[3][4], const float hi[3][4], float tMax,
                       float tEntry[4]) const {
    constexpr float kFarScale = 1.0f + 2.0f * gammaBound(3);
#if CANDELA_HOST_SSE
    __m128 t0 = _mm_setzero_ps(), t1 = _mm_set1_ps(tMax);
    const __m128 scale = _mm_set1_ps(kFarScale);
    for (int axis = 0; axis < 3; ++axis) {
      const __m128 nearPlanes = _mm_loadu_ps(nearIsHi[axis] ? hi[axis] : lo[axis]);
      const __m128 farPlanes = _mm_loadu_ps(nearIsHi[axis] ? lo[axis] : hi[axis]);
      const __m128 o = _mm_set1_ps(origin[axis]), inv = _mm_set1_ps(invDir[axis]);
      const __m128 tNear = _mm_mul_ps(_mm_sub_ps(nearPlanes, o), inv);
      const __m128 tFar = _mm_mul_ps(_mm_mul_ps(_mm_sub_ps(farPlanes, o), inv), scale);
      t0 = _mm_max_ps(tNear, t0);
      t1 = _mm_min_ps(tFar, t1);
    }
    _mm_storeu_ps(tEntry, t0);
    return _mm_movemask_ps(_mm_cmple_ps(t0, t1));
#else
    float t0[4] = {0.0f, 0.0f, 0.0f, 0.0f}, t1[4] = {tMax, tMax, tMax, tMax};
    for (int axis = 0; axis < 3; ++axis) {
      const float* nearPlanes = nearIsHi[axis] ? hi[axis] : lo[axis];
      const float* farPlanes = nearIsHi[axis] ? lo[axis] : hi[axis];
      const float o = origin[axis], inv = invDir[axis];
      for (int c = 0; c < 4; ++c) {
        const float tNear = (nearPlanes[c] - o) * inv;
        const float tFar = (farPlanes[c] - o) * inv * kFarScale;
        t0[c] = tNear > t0[c] ? tNear : t0[c];
        t1[c] = tFar < t1[c] ? tFar : t1[c];
      }
    }
    int mask = 0;
    for (int c = 0; c < 4; ++c) {
      tEntry[c] = t0[c];
      mask |= (t0[c] <= t1[c]) << c;
    }
    return mask;
#endif
  }
};

// Slab test of the ray origin + t * dir, t in [0, tMax], against the closed box [lo, hi];
// invDir = 1 / dir per axis.
CANDELA_HDI bool intersectAabb(const Vec3& lo, const Vec3& hi, const Vec3& origin,
                               const Vec3& invDir, float tMax) {
  float tEntry;
  return RayBoxTester(origin, invDir).hit(lo, hi, tMax, &tEntry);
}

}  // namespace candela
