// EmbreeTracer: the CPU's ray engine on Intel Embree 3 (a tracer in the sense of
// geometry/bvh_tracer.h), over an EmbreeScene (backends/cpu/embree_scene.h).
//
// Embree holds the triangles, as one triangle geometry; the spheres stay candela's own, traced
// inline first, so a ray pays no callback per sphere (Embree's user geometry cost the
// sphere-walled default room a fifth of its speed) and a sphere hit shortens the ray Embree then
// traces. A few spheres are tested four at a time (backends/cpu/sphere_blocks.h), more through a
// BVH over the spheres alone. Hits carry the primitive numbering of geometry/geometry_view.h, so
// the integrator cannot tell the engines apart. A shadow ray's skipped triangle is rejected by a
// context filter that reads it from the intersection context.
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>

#include "backends/cpu/sphere_blocks.h"
#include "geometry/bvh_traverse.h"

namespace candela {

// An intersection context that names the primitive a shadow ray must not hit.
struct EmbreeSkipContext {
  RTCIntersectContext base;  // first, so Embree's pointer to it is a pointer to this
  uint32_t skipPrim;
  uint32_t sphereCount;
};

// Context filter: rejects hits on the skipped triangle.
void rejectSkippedTriangle(const RTCFilterFunctionNArguments* args);
// Geometry filter (intersection and occlusion) of scenes with alpha masks: rejects the hits that
// alphaKeepsHit (geometry/alpha_test.h) rejects; its user data is the scene's GeometryView.
void rejectMaskedHit(const RTCFilterFunctionNArguments* args);

struct EmbreeTracer {
  RTCScene triangles;    // null when the scene has none
  GeometryView spheres;  // the spheres and, when they are not in blocks, their BVH (no triangles)
  SphereBlocksView sphereBlocks;  // the spheres in blocks of four, when they are few; else empty
  uint32_t sphereCount;

  bool closest(const Ray& ray, Hit* hit) const {
    if (!isFiniteRay(ray)) return false;  // Embree's behaviour on NaN rays is undefined
    const bool sphereFound = closestSphereOf(ray, hit);
    if (!triangles) return sphereFound;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayHit;
    setRay(ray, sphereFound ? hit->t : ray.tMax, &rayHit.ray);
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(triangles, &context, &rayHit);
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return sphereFound;
    hit->t = rayHit.ray.tfar;
    hit->prim = sphereCount + rayHit.hit.primID;
    hit->b1 = rayHit.hit.u;
    hit->b2 = rayHit.hit.v;
    return true;
  }

  bool occluded(const Ray& ray, uint32_t skipPrim) const {
    if (!isFiniteRay(ray)) return false;
    if (sphereBlocks.blockCount != 0 ? anySphere(sphereBlocks, ray, skipPrim)
                                     : intersectAny(spheres, ray, skipPrim))
      return true;
    if (!triangles) return false;
    EmbreeSkipContext context;
    rtcInitIntersectContext(&context.base);
    context.skipPrim = skipPrim;
    context.sphereCount = sphereCount;
    if (skipPrim >= sphereCount && skipPrim != 0xffffffffu)
      context.base.filter = rejectSkippedTriangle;
    RTCRay r;
    setRay(ray, ray.tMax, &r);
    rtcOccluded1(triangles, &context.base, &r);
    return r.tfar < 0.0f;  // Embree marks an occluded ray with tfar = -inf
  }

 private:
  bool closestSphereOf(const Ray& ray, Hit* hit) const {
    if (sphereBlocks.blockCount == 0) return intersectClosest(spheres, ray, hit);
    if (!closestSphere(sphereBlocks, ray, ray.tMax, &hit->t, &hit->prim)) return false;
    hit->b1 = hit->b2 = 0.0f;
    return true;
  }

  static void setRay(const Ray& ray, float tMax, RTCRay* r) {
    r->org_x = ray.origin.x;
    r->org_y = ray.origin.y;
    r->org_z = ray.origin.z;
    r->tnear = 0.0f;
    r->dir_x = ray.direction.x;
    r->dir_y = ray.direction.y;
    r->dir_z = ray.direction.z;
    r->time = 0.0f;
    r->tfar = tMax;
    r->mask = 0xffffffffu;
    r->id = 0;
    r->flags = 0;
  }
};

}  // namespace candela
