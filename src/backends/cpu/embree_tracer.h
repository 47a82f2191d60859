// EmbreeTracer: the CPU's ray engine on Intel Embree 3 (a tracer in the sense of
// geometry/bvh_tracer.h), over an EmbreeScene (backends/cpu/embree_scene.h).
//
// The triangles are one Embree triangle geometry and the spheres one user geometry that runs
// candela's own sphere test, so hits carry the primitive numbering of geometry/geometry_view.h
// and the integrator cannot tell the engines apart. A shadow ray's skipped primitive rides in the
// intersection context: the sphere callback reads it, and for a skipped triangle a context filter
// rejects that one triangle's hits.
#pragma once

#include <embree3/rtcore.h>

#include <cstdint>

#include "geometry/bvh_traverse.h"

namespace candela {

// Embree's geometry ids of candela's two primitive kinds.
constexpr unsigned kEmbreeTriangles = 0, kEmbreeSpheres = 1;

// An intersection context that names the primitive a shadow ray must not hit.
struct EmbreeSkipContext {
  RTCIntersectContext base;  // first, so Embree's pointer to it is a pointer to this
  uint32_t skipPrim;
  uint32_t sphereCount;
};

// Context filter: rejects hits on the skipped triangle.
void rejectSkippedTriangle(const RTCFilterFunctionNArguments* args);

struct EmbreeTracer {
  RTCScene scene;
  uint32_t sphereCount;

  bool closest(const Ray& ray, Hit* hit) const {
    if (!isFiniteRay(ray)) return false;  // Embree's behaviour on NaN rays is undefined
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayHit;
    setRay(ray, &rayHit.ray);
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rayHit);
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
    hit->t = rayHit.ray.tfar;
    hit->prim =
        rayHit.hit.geomID == kEmbreeTriangles ? sphereCount + rayHit.hit.primID : rayHit.hit.primID;
    hit->b1 = rayHit.hit.u;
    hit->b2 = rayHit.hit.v;
    return true;
  }

  bool occluded(const Ray& ray, uint32_t skipPrim) const {
    if (!isFiniteRay(ray)) return false;
    EmbreeSkipContext context;
    rtcInitIntersectContext(&context.base);
    context.skipPrim = skipPrim;
    context.sphereCount = sphereCount;
    if (skipPrim >= sphereCount && skipPrim != 0xffffffffu)
      context.base.filter = rejectSkippedTriangle;
    RTCRay r;
    setRay(ray, &r);
    rtcOccluded1(scene, &context.base, &r);
    return r.tfar < 0.0f;  // Embree marks an occluded ray with tfar = -inf
  }

 private:
  static void setRay(const Ray& ray, RTCRay* r) {
    r->org_x = ray.origin.x;
    r->org_y = ray.origin.y;
    r->org_z = ray.origin.z;
    r->tnear = 0.0f;
    r->dir_x = ray.direction.x;
    r->dir_y = ray.direction.y;
    r->dir_z = ray.direction.z;
    r->time = 0.0f;
    r->tfar = ray.tMax;
    r->mask = 0xffffffffu;
    r->id = 0;
    r->flags = 0;
  }
};

}  // namespace candela
