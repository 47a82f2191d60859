// Axis-aligned bounding boxes: the box type used by the BVH build and the slab test used by
// traversal on every device.
//
// An empty box has lo = +max, hi = -max, so growing it by any point or box just works.
#pragma once

#include <cmath>

#include "core/constants.h"
#include "core/float_error.h"
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

namespace detail {

// Entry and exit distances of one slab pair, ordered; the exit is enlarged by the rounding bound.
CANDELA_HDI void slab(float lo, float hi, float origin, float invDir, float* tNear, float* tFar) {
  constexpr float kFarScale = 1.0f + 2.0f * gammaBound(3);
  const float a = (lo - origin) * invDir, b = (hi - origin) * invDir;
  // A NaN is 0 * inf: the ray is parallel to this axis and starts on a slab plane, so it lies in
  // the closed slab for every t. (Left to the comparisons, a direction of -0 would turn the other
  // distance, -inf, into the exit and miss the box.)
  if (a != a || b != b) {
    *tNear = -kInfinity;
    *tFar = kInfinity;
    return;
  }
  *tNear = a < b ? a : b;
  *tFar = (a < b ? b : a) * kFarScale;
}

}  // namespace detail

// Slab test of the ray origin + t * dir, t in [0, tMax], against the box [lo, hi];
// invDir = 1 / dir per axis (an infinity for a zero component is expected and fine).
//
// Robustness (pbrt-v4, section 6.8.2): each slab's far distance is enlarged by 1 + 2 gamma(3), the
// bound on the rounding error of the near and far distances, so a ray that truly touches the box
// is never reported as a miss. Boxes are closed: a ray along a face or edge hits.
// All three axes are evaluated before one final test: no early exit, more parallel arithmetic.
CANDELA_HDI bool intersectAabb(const Vec3& lo, const Vec3& hi, const Vec3& origin,
                               const Vec3& invDir, float tMax) {
  float nx, fx, ny, fy, nz, fz;
  detail::slab(lo.x, hi.x, origin.x, invDir.x, &nx, &fx);
  detail::slab(lo.y, hi.y, origin.y, invDir.y, &ny, &fy);
  detail::slab(lo.z, hi.z, origin.z, invDir.z, &nz, &fz);
  float t0 = 0.0f, t1 = tMax;
  t0 = nx > t0 ? nx : t0;
  t0 = ny > t0 ? ny : t0;
  t0 = nz > t0 ? nz : t0;
  t1 = fx < t1 ? fx : t1;
  t1 = fy < t1 ? fy : t1;
  t1 = fz < t1 ? fz : t1;
  return t0 <= t1;
}

}  // namespace candela
