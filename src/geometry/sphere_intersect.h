// Ray–sphere intersection in world space, float only.
//
// Solves |o + t d - c|^2 = r^2 for the nearest root t in (0, tMax). There is deliberately no
// scene-scale epsilon: secondary rays start at offsetRayOrigin (core/float_error.h), which puts
// them strictly on the side they leave towards, so `t > 0` is the whole self-hit test. A ray whose
// origin lies inside the sphere gets the far root (the exit point).
//
// Numerics (pbrt-v4, section 6.8.4, and "Ray Tracing Gems", chapter 7):
// - the discriminant is computed from the ray's closest-approach vector, r^2 - |perp|^2 factored
//   as (r - |perp|)(r + |perp|), not from b^2 - 4ac, which cancels catastrophically when the
//   sphere is small or far away compared with the origin's distance, or grazed;
// - the roots come from the stable pair q / a and c / q, avoiding the -b + sqrt(...) cancellation.
// What remains is the rounding of o - c itself: hits on a sphere centred 1e5 away (the "walls"
// of our scenes) are accurate to a few ulp(1e5), about 0.02 units, along the normal.
#pragma once

#include <cmath>

#include "core/vec3.h"
#include "geometry/ray.h"
#include "geometry/shapes.h"

namespace candela {

CANDELA_HDI bool intersectSphere(const Sphere& s, const Ray& r, float tMax, float* tHit) {
  const Vec3 oc = r.origin - s.center;
  const Vec3& d = r.direction;
  const float halfB = dot(oc, d);
  const float c = lengthSquared(oc) - s.radius * s.radius;
  // From outside (c > 0) a miss is often clear before any square root or division, which spares
  // most rays most of a room's wall spheres. Moving away (halfB >= 0), both roots are negative
  // (their product c / a is positive, their sum -2 halfB / a not): the right-hand side below is
  // then at most 0. Moving towards it, the near root c / q has q <= -2 halfB, so it lies at least
  // c / (-2 halfB) away, and beyond tMax (a shadow ray's light, a hit already found) it is missed.
  if (c > 0.0f && c >= tMax * (-2.0f * halfB)) return false;
  const float a = lengthSquared(d);

  // Discriminant / 4 = halfB^2 - a c = a (r^2 - |perp|^2), perp = oc minus its projection on d.
  // The miss test compares lengths rather than the product's sign, which underflow could lose.
  const Vec3 perp = oc - (halfB / a) * d;
  const float perpLength = length(perp);
  if (perpLength > s.radius) return false;
  const float discriminant = a * (s.radius - perpLength) * (s.radius + perpLength);

  const float q = -(halfB + copysignf(sqrtf(discriminant), halfB));
  // q == 0 only for a tangent ray starting on the sphere: both roots are 0 and the NaN from c / q
  // below fails every comparison, which reports the correct miss.
  float t0 = q / a, t1 = c / q;
  if (t0 > t1) {
    const float swap = t0;
    t0 = t1;
    t1 = swap;
  }
  if (t0 > 0.0f && t0 < tMax) {
    *tHit = t0;
    return true;
  }
  if (t1 > 0.0f && t1 < tMax) {
    *tHit = t1;
    return true;
  }
  return false;
}

}  // namespace candela
