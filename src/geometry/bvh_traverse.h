// BVH traversal for closest-hit and any-hit (shadow) queries, shared by all backends.
//
// A loop over the flattened depth-first nodes (scene/scene_view.h) with a fixed stack of 64 node
// indices: buildBvh bounds the tree depth by kBvhMaxDepth = 63, and the stack holds at most one
// entry per level. Interior nodes are entered near child first, chosen by the sign of the ray
// direction along the node's split axis (the first child holds the lower coordinates). Hits are
// reported for t in (0, ray.tMax); a scene with no nodes is all miss.
#pragma once

#include <cstdint>

#include "geometry/aabb.h"
#include "geometry/ray.h"
#include "geometry/sphere_intersect.h"
#include "geometry/triangle_intersect.h"
#include "scene/scene_view.h"

namespace candela {

constexpr int kBvhStackSize = 64;

// Intersects primitive `prim` (SceneView numbering) for t in (0, tMax); fills `hit` on a hit.
CANDELA_HDI bool intersectPrimitive(const SceneView& scene, const Ray& ray, uint32_t prim,
                                    float tMax, Hit* hit) {
  if (prim < scene.sphereCount) {
    float t;
    if (!intersectSphere(scene.spheres[prim], ray, tMax, &t)) return false;
    hit->t = t;
    hit->prim = prim;
    hit->b1 = hit->b2 = 0.0f;
    return true;
  }
  const Triangle& tri = scene.triangles[prim - scene.sphereCount];
  TriangleHit th;
  if (!intersectTriangle(scene.positions[tri.v[0]], scene.positions[tri.v[1]],
                         scene.positions[tri.v[2]], ray, tMax, &th)) {
    return false;
  }
  hit->t = th.t;
  hit->prim = prim;
  hit->b1 = th.b1;
  hit->b2 = th.b2;
  return true;
}

namespace detail {

// The one traversal loop. anyHit: stop at the first hit not on `skipPrim`; otherwise find the
// nearest hit. Returns whether a hit was found; `hit` receives it (closest mode).
//
// Ordered traversal: at an interior node both children's boxes are tested, the nearer child is
// visited next and the farther one is pushed with its entry distance, so that once a nearer hit
// is known, popped subtrees that start beyond it are skipped without touching their nodes.
CANDELA_HDI bool traverseBvh(const SceneView& scene, const Ray& ray, bool anyHit, uint32_t skipPrim,
                             Hit* hit) {
  if (scene.nodeCount == 0) return false;
  const RayBoxTester box(ray.origin, Vec3(1.0f / ray.direction.x, 1.0f / ray.direction.y,
                                          1.0f / ray.direction.z));
  float tMax = ray.tMax;
  float tEntry;
  if (!box.hit(scene.nodes[0].boundsMin, scene.nodes[0].boundsMax, tMax, &tEntry)) return false;

  bool found = false;
  uint32_t stackNode[kBvhStackSize];
  float stackEntry[kBvhStackSize];
  int stackSize = 0;
  uint32_t current = 0;
  for (;;) {
    const BvhNode& node = scene.nodes[current];
    if (node.primCount == 0) {
      const uint32_t first = current + 1, second = node.offset;
      const BvhNode& a = scene.nodes[first];
      const BvhNode& b = scene.nodes[second];
      float tA, tB;
      const bool hitA = box.hit(a.boundsMin, a.boundsMax, tMax, &tA);
      const bool hitB = box.hit(b.boundsMin, b.boundsMax, tMax, &tB);
      if (hitA && hitB) {
        const bool aFirst = tA <= tB;
        stackNode[stackSize] = aFirst ? second : first;
        stackEntry[stackSize++] = aFirst ? tB : tA;
        current = aFirst ? first : second;
        continue;
      }
      if (hitA || hitB) {
        current = hitA ? first : second;
        continue;
      }
    } else {
      for (uint32_t i = 0; i < node.primCount; ++i) {
        const uint32_t prim = scene.primIndices[node.offset + i];
        if (prim == skipPrim) continue;
        if (intersectPrimitive(scene, ray, prim, tMax, hit)) {
          if (anyHit) return true;
          found = true;
          tMax = hit->t;  // later candidates must be nearer
        }
      }
    }
    // Pop the next subtree that may still hold a nearer hit.
    do {
      if (stackSize == 0) return found;
      current = stackNode[--stackSize];
    } while (stackEntry[stackSize] > tMax);
  }
}

}  // namespace detail

// Nearest hit of `ray` for t in (0, ray.tMax). On a hit fills `hit` and returns true; on a miss
// returns false and leaves `hit` untouched.
CANDELA_HDI bool intersectClosest(const SceneView& scene, const Ray& ray, Hit* hit) {
  return detail::traverseBvh(scene, ray, false, 0xffffffffu, hit);
}

// Whether anything but primitive `skipPrim` (0xffffffff: none) blocks `ray` for t in
// (0, ray.tMax). Used by shadow rays; a ray towards a point sampled on a sphere light skips
// that light's own sphere.
CANDELA_HDI bool intersectAny(const SceneView& scene, const Ray& ray, uint32_t skipPrim) {
  Hit unused;
  return detail::traverseBvh(scene, ray, true, skipPrim, &unused);
}

// Nearest hit by testing every primitive, ignoring the BVH: the reference for tests and
// benchmarks. Same contract as intersectClosest.
CANDELA_HDI bool intersectClosestBruteForce(const SceneView& scene, const Ray& ray, Hit* hit) {
  float tMax = ray.tMax;
  bool found = false;
  for (uint32_t prim = 0; prim < scene.primitiveCount(); ++prim) {
    if (intersectPrimitive(scene, ray, prim, tMax, hit)) {
      found = true;
      tMax = hit->t;
    }
  }
  return found;
}

// Any-hit by testing every primitive; the reference for intersectAny.
CANDELA_HDI bool intersectAnyBruteForce(const SceneView& scene, const Ray& ray, uint32_t skipPrim) {
  Hit unused;
  for (uint32_t prim = 0; prim < scene.primitiveCount(); ++prim)
    if (prim != skipPrim && intersectPrimitive(scene, ray, prim, ray.tMax, &unused)) return true;
  return false;
}

}  // namespace candela
