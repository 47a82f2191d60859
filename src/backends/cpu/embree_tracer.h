// EmbreeTracer: the CPU's ray engine on Intel Embree 3 (a tracer in the sense of
// geometry/bvh_tracer.h), over an EmbreeScene (backends/cpu/embree_scene.h).
//
// Embree holds the triangles (backends/cpu/embree_scene.h: in runs of objects, and the objects
// that repeat a mesh as instances of one); the spheres stay candela's own, traced
// inline first, so a ray pays no callback per sphere (Embree's user geometry cost the
// sphere-walled default room a fifth of its speed) and a sphere hit shortens the ray Embree then
// traces. A few spheres are tested in blocks of 4 or 8 (backends/cpu/sphere_blocks.h), more
// through a BVH over the spheres alone. A scene of very few triangles has them in blocks too
// (backends/cpu/triangle_blocks.h), and no Embree scene. Hits carry the primitive numbering of
// geometry/geometry_view.h, so the integrator cannot tell the engines apart. A shadow ray's
// skipped triangle is rejected by a context filter that reads it from the intersection context.
#pragma once

#include <embree3/rtcore.h>
#include <immintrin.h>

#include <cstdint>

#include "backends/cpu/finite_ray.h"
#include "backends/cpu/sphere_blocks.h"
#include "backends/cpu/triangle_blocks.h"
#include "core/constants.h"
#include "geometry/bvh_traverse.h"

namespace candela {

// The intersection context of every query: what the filters need beyond Embree's hit. Ray id k
// (RTCRay::id) is rays[k] in world space (within an instance Embree hands a filter the ray in
// the instance's space), and skips primitive skipPrims[k] (none where skipPrims is null).
struct EmbreeQueryContext {
  RTCIntersectContext base;  // first, so Embree's pointer to it is a pointer to this
  const Ray* rays;
  const uint32_t* skipPrims;
  const uint32_t* firstTriangleOf;  // EmbreeTracer::firstTriangleOf
  uint32_t sphereCount;
};

// The scene's triangle that an Embree hit names: its primitive in the geometry it hit, shifted
// by where that geometry's triangles start (the instance's, when the geometry is one's).
inline uint32_t triangleOfHit(const uint32_t* firstTriangleOf, unsigned geomID, unsigned instID,
                              unsigned primID) {
  return firstTriangleOf[instID != RTC_INVALID_GEOMETRY_ID ? instID : geomID] + primID;
}

// Context filter: rejects hits on the triangles the rays skip.
void rejectSkippedTriangle(const RTCFilterFunctionNArguments* args);
// Geometry filter (intersection and occlusion) of scenes with alpha masks: rejects the hits that
// alphaKeepsHit (geometry/alpha_test.h) rejects; its user data is the scene's GeometryView.
void rejectMaskedHit(const RTCFilterFunctionNArguments* args);

struct EmbreeTracer {
  // A pixel's camera rays, and the shadow rays of their first interactions, go to Embree 16 at
  // a time (rtcIntersect16 and rtcOccluded16, which Embree splits where the CPU has narrower
  // vectors): docs/performance.md has the gain.
  static constexpr uint32_t kPacketWidth = 16;  // RTCRayHit16's lanes
  RTCScene triangles;    // null when the scene has none
  // Where the triangles of each geometry of `triangles` start among the scene's, by geometry ID:
  // Embree numbers a hit's triangle within the geometry (or the instance) it hit.
  const uint32_t* firstTriangleOf;
  // Whether packets may be traced as coherent: not through instances, where Debian's Embree
  // 3.13.5 never returns from a coherent rtcOccluded16 with 16-wide (AVX-512) kernels.
  bool coherentPackets;
  GeometryView spheres;  // the spheres and, when they are not in blocks, their BVH (no triangles)
  SphereBlocksView sphereBlocks;  // the spheres in blocks, when they are few; else empty
  uint32_t sphereCount;
  TriangleBlocksView triangleBlocks;  // the triangles in blocks, when they are few; else empty
  // The scene, whose motion BVH holds what moves while the shutter is open (geometry/motion.h),
  // traced here before the triangles; null where nothing moves.
  const GeometryView* moving = nullptr;

  bool closest(const Ray& ray, Hit* hit) const {
    if (!isFiniteRayCpu(ray)) return false;  // Embree's behaviour on NaN rays is undefined
    const bool sphereFound = closestSphereOf(ray, hit);
    if (triangleBlocks.blockCount != 0) return closestTriangleOf(ray, sphereFound, hit);
    if (!triangles) return sphereFound;
    EmbreeQueryContext context = queryContext(&ray, nullptr);
    RTCRayHit rayHit;
    setRay(ray, sphereFound ? hit->t : ray.tMax, &rayHit.ray);
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(triangles, &context.base, &rayHit);
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return sphereFound;
    hit->t = rayHit.ray.tfar;
    hit->prim = sphereCount + triangleOfHit(firstTriangleOf, rayHit.hit.geomID,
                                            rayHit.hit.instID[0], rayHit.hit.primID);
    hit->b1 = rayHit.hit.u;
    hit->b2 = rayHit.hit.v;
    return true;
  }

  // closest for rays[0, n), n <= kPacketWidth, as one Embree packet (ray by ray where the
  // triangles are in blocks): hits[i] is invalid where ray i hits nothing.
  void closestPacket(const Ray* rays, uint32_t n, Hit* hits) const {
    if (triangleBlocks.blockCount != 0) {
      for (uint32_t i = 0; i < n; ++i) {
        hits[i] = Hit();
        closest(rays[i], &hits[i]);
      }
      return;
    }
    alignas(64) int valid[kPacketWidth];
    alignas(64) RTCRayHit16 packet;
    bool any = false;
    for (uint32_t i = 0; i < kPacketWidth; ++i) {
      valid[i] = 0;
      setInactiveLane(i, &packet.ray);
      packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
      packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
      if (i >= n) continue;
      hits[i] = Hit();
      if (!isFiniteRayCpu(rays[i])) continue;
      Hit sphere;
      const bool sphereFound = closestSphereOf(rays[i], &sphere);
      if (sphereFound) hits[i] = sphere;
      if (!triangles) continue;
      valid[i] = -1;
      any = true;
      setLane(rays[i], sphereFound ? hits[i].t : rays[i].tMax, i, &packet.ray);
    }
    if (!any) return;
    EmbreeQueryContext context = queryContext(rays, nullptr);
    context.base.flags = packetFlags();
    rtcIntersect16(valid, triangles, &context.base, &packet);
    for (uint32_t i = 0; i < n; ++i) {
      if (!valid[i] || packet.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) continue;
      hits[i].t = packet.ray.tfar[i];
      hits[i].prim = sphereCount + triangleOfHit(firstTriangleOf, packet.hit.geomID[i],
                                                 packet.hit.instID[0][i], packet.hit.primID[i]);
      hits[i].b1 = packet.hit.u[i];
      hits[i].b2 = packet.hit.v[i];
    }
  }

  bool occluded(const Ray& ray, uint32_t skipPrim) const {
    if (!isFiniteRayCpu(ray)) return false;
    if (anySphereOf(ray, skipPrim)) return true;
    // A skipped sphere (or none) wraps to an index beyond every triangle's.
    if (triangleBlocks.blockCount != 0)
      return anyTriangle(triangleBlocks, ray, skipPrim - sphereCount);
    if (!triangles) return false;
    EmbreeQueryContext context = queryContext(&ray, &skipPrim);
    if (skipsTriangle(skipPrim)) context.base.filter = rejectSkippedTriangle;
    RTCRay r;
    setRay(ray, ray.tMax, &r);
    rtcOccluded1(triangles, &context.base, &r);
    return r.tfar < 0.0f;  // Embree marks an occluded ray with tfar = -inf
  }

  // occluded for rays[0, n), n <= kPacketWidth, ray k skipping skipPrims[k], as one Embree
  // packet (ray by ray where the triangles are in blocks): blocked[k] is the answer for ray k.
  void occludedPacket(const Ray* rays, const uint32_t* skipPrims, uint32_t n, bool* blocked) const {
    if (triangleBlocks.blockCount != 0) {
      for (uint32_t k = 0; k < n; ++k) blocked[k] = occluded(rays[k], skipPrims[k]);
      return;
    }
    alignas(64) int valid[kPacketWidth];
    alignas(64) RTCRay16 packet;
    bool any = false, skips = false;
    for (uint32_t k = 0; k < kPacketWidth; ++k) {
      valid[k] = 0;
      setInactiveLane(k, &packet);
      if (k >= n) continue;
      blocked[k] = false;
      if (!isFiniteRayCpu(rays[k])) continue;
      if (anySphereOf(rays[k], skipPrims[k])) {
        blocked[k] = true;
        continue;
      }
      if (!triangles) continue;
      valid[k] = -1;
      any = true;
      skips = skips || skipsTriangle(skipPrims[k]);
      setLane(rays[k], rays[k].tMax, k, &packet);
    }
    if (!any) return;
    EmbreeQueryContext context = queryContext(rays, skipPrims);
    context.base.flags = packetFlags();
    if (skips) context.base.filter = rejectSkippedTriangle;
    rtcOccluded16(valid, triangles, &context.base, &packet);
    for (uint32_t k = 0; k < n; ++k)
      if (valid[k] && packet.tfar[k] < 0.0f) blocked[k] = true;
  }

 private:
  EmbreeQueryContext queryContext(const Ray* rays, const uint32_t* skipPrims) const {
    EmbreeQueryContext context;
    rtcInitIntersectContext(&context.base);
    context.rays = rays;
    context.skipPrims = skipPrims;
    context.firstTriangleOf = firstTriangleOf;
    context.sphereCount = sphereCount;
    return context;
  }

  RTCIntersectContextFlags packetFlags() const {
    return coherentPackets ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                           : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
  }

  // The nearest sphere hit, or the nearer hit of a primitive that moves.
  bool closestSphereOf(const Ray& ray, Hit* hit) const {
    bool found = false;
    if (sphereCount != 0) {
      if (sphereBlocks.blockCount == 0) {
        found = intersectClosest(spheres, ray, hit);
      } else if (closestSphere(sphereBlocks, ray, ray.tMax, &hit->t, &hit->prim)) {
        hit->b1 = hit->b2 = 0.0f;
        found = true;
      }
    }
    if (moving && intersectClosestMoving(*moving, ray, found ? hit->t : ray.tMax, hit)) return true;
    return found;
  }

  // The nearest of the sphere hit in *hit (where sphereFound) and a triangle hit in the blocks.
  bool closestTriangleOf(const Ray& ray, bool sphereFound, Hit* hit) const {
    uint32_t triangle;
    if (!closestTriangle(triangleBlocks, ray, sphereFound ? hit->t : ray.tMax, &hit->t, &triangle,
                         &hit->b1, &hit->b2))
      return sphereFound;
    hit->prim = sphereCount + triangle;
    return true;
  }

  // Whether a sphere, or a primitive that moves, blocks the ray.
  bool anySphereOf(const Ray& ray, uint32_t skipPrim) const {
    if (sphereCount != 0 && (sphereBlocks.blockCount != 0 ? anySphere(sphereBlocks, ray, skipPrim)
                                                          : intersectAny(spheres, ray, skipPrim)))
      return true;
    return moving && intersectAnyMoving(*moving, ray, skipPrim);
  }

  bool skipsTriangle(uint32_t skipPrim) const {
    return skipPrim >= sphereCount && skipPrim != 0xffffffffu;
  }

  // Lane k of a packet: `ray` up to tMax, with id k.
  static void setLane(const Ray& ray, float tMax, uint32_t k, RTCRay16* r) {
    r->org_x[k] = ray.origin.x;
    r->org_y[k] = ray.origin.y;
    r->org_z[k] = ray.origin.z;
    r->tnear[k] = 0.0f;
    r->dir_x[k] = ray.direction.x;
    r->dir_y[k] = ray.direction.y;
    r->dir_z[k] = ray.direction.z;
    r->time[k] = 0.0f;
    r->tfar[k] = tMax;
    r->mask[k] = 0xffffffffu;
    r->id[k] = k;
    r->flags[k] = 0;
  }

  // Lane k of a packet, left out. Where the CPU has no 16-wide packets (below AVX-512) Embree
  // traces a packet of 16 through its ray-stream path, which ignores the valid mask and leaves
  // out the lanes whose tnear exceeds tfar instead: every lane must say whether it is one.
  static void setInactiveLane(uint32_t k, RTCRay16* r) {
    r->org_x[k] = r->org_y[k] = r->org_z[k] = 0.0f;
    r->dir_x[k] = r->dir_y[k] = 0.0f;
    r->dir_z[k] = 1.0f;
    r->tnear[k] = kInfinity;
    r->tfar[k] = -kInfinity;
    r->time[k] = 0.0f;
    r->mask[k] = 0;
    r->id[k] = k;
    r->flags[k] = 0;
  }

  // Origin and tnear, direction and time, each written as the one 16-byte store that Embree then
  // loads them as: a 16-byte load across smaller stores just made cannot take their values from
  // the store buffer, and waits for them (a store-forwarding stall) in every query.
  static void setRay(const Ray& ray, float tMax, RTCRay* r) {
    _mm_store_ps(&r->org_x, _mm_setr_ps(ray.origin.x, ray.origin.y, ray.origin.z, 0.0f));
    _mm_store_ps(&r->dir_x, _mm_setr_ps(ray.direction.x, ray.direction.y, ray.direction.z, 0.0f));
    r->tfar = tMax;
    r->mask = 0xffffffffu;
    r->id = 0;
    r->flags = 0;
  }
};

}  // namespace candela
