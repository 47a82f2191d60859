// Watertight ray–triangle intersection (Woop, Benthin and Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2013), in the form of pbrt-v4's Triangle::Intersect, float only.
//
// The vertices are moved into a ray space where the ray is the +z axis from the origin, and the
// 2D edge functions of the projected triangle decide the hit. Watertightness follows from two
// facts: a vertex gets exactly the same ray-space coordinates in every triangle that shares it
// (one helper transforms each vertex alike), and the sign of each edge function is exact, so two
// triangles sharing an edge classify every ray consistently; zero, "on the edge", counts as inside
// for both. No back-face culling: both windings hit.
//
// The returned t is conservatively positive (pbrt's deltaT bound on the rounding error of t), so
// a ray spawned with offsetRayOrigin never re-hits the triangle it leaves.
#pragma once

#include <cmath>

#include "core/float_error.h"
#include "core/vec3.h"
#include "geometry/ray.h"

namespace candela {

struct TriangleHit {
  float t;           // ray parameter of the hit
  float b0, b1, b2;  // barycentrics of p0, p1, p2; they sum to 1
};

namespace detail {

// a*b - c*d with the sign of the exact value (Kahan's algorithm: relative error below 2 ulp, and
// zero only when the exact value is zero).
CANDELA_HDI float differenceOfProductsExact(float a, float b, float c, float d) {
  const float cd = c * d;
  const float err = fmaf(-c, d, cd);  // exactly cd - c*d
  const float dop = fmaf(a, b, -cd);
  return dop + err;
}

// Edge function a*b - c*d whose sign is exact. Where the compiler may fuse a multiply-add
// (nvcc always, host compilers targeting FMA hardware) a plain a*b - c*d can come out with the
// wrong sign, so Kahan's form is used. Without FMA hardware there is no fusion: rounding is
// monotonic, so a*b - c*d has the exact sign or is 0, and only a 0 needs the exact (slower,
// library fmaf) recomputation, as pbrt-v4 does with its double-precision fallback.
CANDELA_HDI float edgeFunction(float a, float b, float c, float d) {
#if CANDELA_DEVICE_CODE || defined(__FMA__) || defined(__ARM_FEATURE_FMA)
  return differenceOfProductsExact(a, b, c, d);
#else
  const float e = a * b - c * d;
  return e != 0.0f ? e : differenceOfProductsExact(a, b, c, d);
#endif
}

// Largest absolute value of three; comparisons instead of fmaxf, which host compilers do not
// inline.
CANDELA_HDI float maxAbs3(float a, float b, float c) {
  a = fabsf(a), b = fabsf(b), c = fabsf(c);
  const float ab = a > b ? a : b;
  return ab > c ? ab : c;
}

// The ray-space shear, applied identically to every vertex (see the file comment).
template <class Axes>
CANDELA_HDI Vec3 toRaySpace(const Vec3& p, const Vec3& origin, const Axes& k, float sx, float sy,
                            float sz) {
  const Vec3 q = p - origin;
  const float z = q[k.z];
  return {q[k.x] + sx * z, q[k.y] + sy * z, sz * z};
}

// The permutation that makes the ray's dominant axis z: known at compile time (each of the three
// is its own copy of the test, so coordinates are picked without selects), or at run time.
template <int X, int Y, int Z>
struct FixedAxes {
  static constexpr int x = X, y = Y, z = Z;
};
struct RuntimeAxes {
  int x, y, z;
};

template <class Axes>
CANDELA_HDI bool intersectTriangleAlong(const Axes& k, const Vec3& p0, const Vec3& p1,
                                        const Vec3& p2, const Ray& ray, float tMax,
                                        TriangleHit* hit) {
  // Ray space: permute so the ray's dominant axis is z, then shear the ray onto +z.
  const Vec3& d = ray.direction;
  const float sz = 1.0f / d[k.z];
  const float sx = -d[k.x] * sz, sy = -d[k.y] * sz;
  const Vec3 q0 = toRaySpace(p0, ray.origin, k, sx, sy, sz);
  const Vec3 q1 = toRaySpace(p1, ray.origin, k, sx, sy, sz);
  const Vec3 q2 = toRaySpace(p2, ray.origin, k, sx, sy, sz);

  // Edge functions: e_i is twice the signed area of (origin, next, next-next) for vertex i.
  const float e0 = edgeFunction(q1.x, q2.y, q1.y, q2.x);
  const float e1 = edgeFunction(q2.x, q0.y, q2.y, q0.x);
  const float e2 = edgeFunction(q0.x, q1.y, q0.y, q1.x);
  if ((e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f)) return false;
  const float det = e0 + e1 + e2;
  if (det == 0.0f) return false;

  // t scaled by det; compare before dividing so misses cost no division.
  const float tScaled = e0 * q0.z + e1 * q1.z + e2 * q2.z;
  if (det < 0.0f && (tScaled >= 0.0f || tScaled < tMax * det)) return false;
  if (det > 0.0f && (tScaled <= 0.0f || tScaled > tMax * det)) return false;
  const float invDet = 1.0f / det;
  const float t = tScaled * invDet;
  if (t >= tMax) return false;

  // Conservative bound on the error of t (pbrt-v4, section 6.8.7): accept only t > deltaT.
  const float maxZt = maxAbs3(q0.z, q1.z, q2.z);
  const float maxXt = maxAbs3(q0.x, q1.x, q2.x);
  const float maxYt = maxAbs3(q0.y, q1.y, q2.y);
  const float deltaZ = gammaBound(3) * maxZt;
  const float deltaX = gammaBound(5) * (maxXt + maxZt);
  const float deltaY = gammaBound(5) * (maxYt + maxZt);
  const float deltaE = 2.0f * (gammaBound(2) * maxXt * maxYt + deltaY * maxXt + deltaX * maxYt);
  const float maxE = maxAbs3(e0, e1, e2);
  const float deltaT =
      3.0f * (gammaBound(3) * maxE * maxZt + deltaE * maxZt + deltaZ * maxE) * fabsf(invDet);
  if (t <= deltaT) return false;
  // Degenerate triangles have no normal to shade with; report no hit. Tested last: most tests
  // miss earlier, and this cross product was about a tenth of the test's work.
  if (lengthSquared(cross(p2 - p0, p1 - p0)) == 0.0f) return false;

  hit->t = t;
  hit->b0 = e0 * invDet;
  hit->b1 = e1 * invDet;
  hit->b2 = e2 * invDet;
  return true;
}

}  // namespace detail

// Nearest-or-only hit of the ray with triangle (p0, p1, p2) for t in (0, tMax). Kept out of
// line on the CPU: inlined, its three copies pushed the sphere test in the traversal loop out of
// line too, and a room's walls then cost a call each (docs/performance.md, cae5563).
#if !CANDELA_DEVICE_CODE && defined(__GNUC__)
__attribute__((noinline))
#endif
CANDELA_HDI bool intersectTriangle(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Ray& ray,
                                   float tMax, TriangleHit* hit) {
  const int kz = maxDimension(abs(ray.direction));
#if CANDELA_DEVICE_CODE
  // One copy on the GPU: neighbouring threads' rays often differ in their dominant axis, and
  // three copies would run one after another.
  const int kx = kz == 2 ? 0 : kz + 1;
  const int ky = kx == 2 ? 0 : kx + 1;
  return detail::intersectTriangleAlong(detail::RuntimeAxes{kx, ky, kz}, p0, p1, p2, ray, tMax,
                                        hit);
#else
  // On the CPU the branch follows the ray, the same for all its triangles, and each copy reads
  // fixed coordinates: the runtime permutation's selects were about a fifth of the test's
  // instructions.
  switch (kz) {
    case 0:
      return detail::intersectTriangleAlong(detail::FixedAxes<1, 2, 0>(), p0, p1, p2, ray, tMax,
                                            hit);
    case 1:
      return detail::intersectTriangleAlong(detail::FixedAxes<2, 0, 1>(), p0, p1, p2, ray, tMax,
                                            hit);
    default:
      return detail::intersectTriangleAlong(detail::FixedAxes<0, 1, 2>(), p0, p1, p2, ray, tMax,
                                            hit);
  }
#endif
}

}  // namespace candela
