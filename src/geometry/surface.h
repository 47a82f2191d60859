// Surface reconstruction: from a traversal Hit to the point, normals, error bound and material
// the integrator shades with. Done once per path vertex, for the winning hit only.
//
// Conventions:
// - ng is the unit geometric normal towards the primitive's OUTSIDE: outward for spheres,
//   normalize((p1 - p0) x (p2 - p0)) for triangles. It is never flipped towards the ray; the
//   integrator decides front and back with dot(wo, ng).
// - ns is the unit shading normal, always in ng's hemisphere.
// - p carries a per-axis absolute error bound (pbrt-v4, section 6.8.5) for offsetRayOrigin.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/constants.h"
#include "core/float_error.h"
#include "core/vec3.h"
#include "geometry/geometry_view.h"
#include "geometry/motion.h"
#include "geometry/ray.h"
#include "geometry/surface_uv.h"

namespace candela {

struct SurfacePoint {
  Vec3 p;      // world-space position
  Vec3 error;  // absolute bound on the error of p, per axis
  Vec3 ng;     // unit geometric normal, towards the primitive's outside
  Vec3 ns;     // unit shading normal, dot(ns, ng) >= 0
  // A face shaded by its vertex normals: the step from p out to the smooth surface that they
  // describe (terminatorLift), on the side they face; zero elsewhere.
  Vec3 lift = Vec3(0.0f);
  uint32_t material;
  // The time of the ray that found the point (Ray::time): the rays that leave it take it on.
  float time = 0.0f;
};

// Hanika 2021, "Hacking the Shadow Terminator": p (barycentrics b of the face with vertices v
// and unit vertex normals n, all on one side of it) raised along each vertex normal by as far as
// it lies below that vertex's tangent plane, weighted by its barycentric. Where a coarse mesh
// curves outwards, the point lands near the smooth surface its normals describe; where it is
// flat or curves inwards, the step is zero.
CANDELA_HDI Vec3 terminatorLift(const Vec3& p, const Vec3 (&v)[3], const Vec3 (&n)[3],
                                const float (&b)[3]) {
  Vec3 lift(0.0f);
  for (int i = 0; i < 3; ++i) lift -= (b[i] * minf(0.0f, dot(p - v[i], n[i]))) * n[i];
  return lift;
}

// The point of sphere s at `local` from its centre (|local| the radius, up to rounding), within
// *error per axis: the point lies within gamma(5) |local| of the surface (pbrt-v4), and adding the
// centre rounds once more, by at most gamma(1) |p|, the term that dominates for small spheres far
// from the world origin.
CANDELA_HDI Vec3 spherePoint(const Sphere& s, const Vec3& local, Vec3* error) {
  const Vec3 p = s.center + local;
  *error = gammaBound(5) * abs(local) + gammaBound(1) * abs(p);
  return p;
}

// The point at barycentrics (1 - b1 - b2, b1, b2) of the triangle (p0, p1, p2), within *error per
// axis. Weights summing to 1 (up to rounding) keep the point on the triangle's plane however
// inaccurate the barycentrics are, so the error is that of the interpolation alone. Its bound
// gamma(7) (pbrt-v4) also covers the rounding of b0 = 1 - b1 - b2.
CANDELA_HDI Vec3 trianglePoint(const Vec3& p0, const Vec3& p1, const Vec3& p2, float b1, float b2,
                               Vec3* error) {
  const Vec3 w0 = (1.0f - b1 - b2) * p0, w1 = b1 * p1, w2 = b2 * p2;
  *error = gammaBound(7) * (abs(w0) + abs(w1) + abs(w2));
  return w0 + w1 + w2;
}

CANDELA_HDI SurfacePoint sphereSurfaceAt(const Sphere& s, const Ray& ray, float t) {
  SurfacePoint sp;
  // Reproject the hit onto the sphere, so that its error bound holds however inaccurate t was.
  Vec3 local = (ray.origin + t * ray.direction) - s.center;
  const float len = length(local);
  local = len > 0.0f ? local * (s.radius / len) : Vec3(0.0f, s.radius, 0.0f);
  sp.p = spherePoint(s, local, &sp.error);
  sp.ng = normalize(local);
  sp.ns = sp.ng;
  sp.material = s.material;
  return sp;
}

// The surface of triangle `tri` at barycentrics (b1, b2); with kMoving where it stands at step
// `step` of its motion (geometry/motion.h), else where the scene's arrays have it.
template <bool kMoving>
CANDELA_HDI SurfacePoint triangleSurfaceAt(const GeometryView& scene, const Triangle& tri, float b1,
                                           float b2, MotionStep step = MotionStep()) {
  SurfacePoint sp;
  Vec3 p[3];
  if constexpr (kMoving) {
    for (int k = 0; k < 3; ++k) p[k] = movingPosition(scene, tri.v[k], step);
  } else {
    for (int k = 0; k < 3; ++k) p[k] = scene.positions[tri.v[k]];
  }
  const float b0 = 1.0f - b1 - b2;
  sp.p = trianglePoint(p[0], p[1], p[2], b1, b2, &sp.error);
  sp.ng = normalize(cross(p[1] - p[0], p[2] - p[0]));
  sp.ns = sp.ng;
  if (scene.normalCount != 0) {
    const OctNormal n0 = scene.normals[tri.v[0]];
    const OctNormal n1 = scene.normals[tri.v[1]];
    const OctNormal n2 = scene.normals[tri.v[2]];
    if (!n0.isNone() && !n1.isNone() && !n2.isNone()) {
      Vec3 d[3];
      if constexpr (kMoving) {
        for (int k = 0; k < 3; ++k) d[k] = movingNormal(scene, tri.v[k], step);
      } else {
        d[0] = decodeOctNormal(n0), d[1] = decodeOctNormal(n1), d[2] = decodeOctNormal(n2);
      }
      const Vec3 n = b0 * d[0] + b1 * d[1] + b2 * d[2];
      // Opposite vertex normals can cancel; the face normal is the only sensible fallback.
      if (lengthSquared(n) > 0.0f) sp.ns = faceForward(normalize(n), sp.ng);
      // Normals on both sides of the face describe no surface to raise the point to.
      const float s0 = dot(d[0], sp.ng), s1 = dot(d[1], sp.ng), s2 = dot(d[2], sp.ng);
      if ((s0 > 0.0f && s1 > 0.0f && s2 > 0.0f) || (s0 < 0.0f && s1 < 0.0f && s2 < 0.0f))
        sp.lift = terminatorLift(sp.p, p, d, {b0, b1, b2});
    }
  }
  sp.material = tri.material;
  return sp;
}

// The surface at `hit` of a primitive that moves, where it stands at the ray's time. Out of line on
// the CPU: scenes where nothing moves never call it.
CANDELA_HD_CPU_CALL SurfacePoint movingSurfaceAt(const GeometryView& scene, const Ray& ray,
                                                 const Hit& hit) {
  const MotionStep step = motionStepAt(scene, ray.time);
  if (hit.prim < scene.sphereCount)
    return sphereSurfaceAt(sphereAt(scene, hit.prim, step), ray, hit.t);
  return triangleSurfaceAt<true>(scene, scene.triangles[hit.prim - scene.sphereCount], hit.b1,
                                 hit.b2, step);
}

// The surface at `hit`, which `ray` found (intersectClosest or intersectPrimitive), where it
// stands at the ray's time.
CANDELA_HDI_ALWAYS SurfacePoint surfaceAt(const GeometryView& scene, const Ray& ray,
                                          const Hit& hit) {
  SurfacePoint sp;
  const bool sphere = hit.prim < scene.sphereCount;
  if (sphere ? sphereMoves(scene, hit.prim)
             : triangleMoves(scene, scene.triangles[hit.prim - scene.sphereCount]))
    sp = movingSurfaceAt(scene, ray, hit);
  else if (sphere)
    sp = sphereSurfaceAt(scene.spheres[hit.prim], ray, hit.t);
  else
    sp = triangleSurfaceAt<false>(scene, scene.triangles[hit.prim - scene.sphereCount], hit.b1,
                                  hit.b2);
  sp.time = ray.time;
  return sp;
}

// The texture coordinates at `hit` (geometry/surface_uv.h), whose surface is `sp`: computed only
// where a texture asks, since a sphere's cost two inverse trigonometric functions.
CANDELA_HDI Vec2 surfaceUv(const GeometryView& scene, const Hit& hit, const SurfacePoint& sp) {
  if (hit.prim < scene.sphereCount) return sphereUv(sp.ng);
  return triangleUv(scene, scene.triangles[hit.prim - scene.sphereCount], hit.b1, hit.b2);
}

}  // namespace candela
