// BVH traversal for closest-hit and any-hit (shadow) queries, shared by all backends.
//
// A loop over the 4-wide nodes (geometry/bvh_node.h) with a fixed stack: buildBvh bounds the tree
// depth by kBvhMaxDepth = 63, and each level leaves at most three entries on the stack. Hits are
// reported for t in (0, ray.tMax); a scene with no nodes is all miss.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/bits.h"
#include "core/check.h"
#include "geometry/aabb.h"
#include "geometry/alpha_test.h"
#include "geometry/geometry_view.h"
#include "geometry/motion.h"
#include "geometry/ray.h"
#include "geometry/sphere_intersect.h"
#include "geometry/triangle_intersect.h"

namespace candela {

// Each wide node pushes at most three entries and the tree is at most kBvhMaxDepth (63) deep.
constexpr int kBvhStackSize = 3 * 63 + 1;

// Intersects primitive `prim` (GeometryView numbering) for t in (0, tMax); fills `hit` on a hit.
// A triangle hit that its material's alpha mask rejects (geometry/alpha_test.h) is no hit. With
// kMoving the primitive is taken where it stands at the ray's time (geometry/motion.h): the
// motion BVH's leaves; the scene's BVH holds only primitives that stand still. `step` is
// motionStepAt of the ray's time (read only with kMoving).
template <bool kMoving = false>
CANDELA_HDI bool intersectPrimitive(const GeometryView& scene, const Ray& ray, uint32_t prim,
                                    float tMax, Hit* hit, MotionStep step = MotionStep()) {
  if (prim < scene.sphereCount) {
    float t;
    if constexpr (kMoving) {
      if (!intersectSphere(sphereAt(scene, prim, step), ray, tMax, &t)) return false;
    } else if (!intersectSphere(scene.spheres[prim], ray, tMax, &t)) {
      return false;
    }
    hit->t = t;
    hit->prim = prim;
    hit->b1 = hit->b2 = 0.0f;
    return true;
  }
  const Triangle& tri = scene.triangles[prim - scene.sphereCount];
  TriangleHit th;
  if constexpr (kMoving) {
    Vec3 p[3];
    triangleCornersAt(scene, tri, step, p);
    if (!intersectTriangle(p[0], p[1], p[2], ray, tMax, &th)) return false;
  } else if (!intersectTriangle(scene.positions[tri.v[0]], scene.positions[tri.v[1]],
                                scene.positions[tri.v[2]], ray, tMax, &th)) {
    return false;
  }
  if (!alphaKeepsHit(scene, tri, th.b1, th.b2, ray)) return false;  // masked out: not a surface
  hit->t = th.t;
  hit->prim = prim;
  hit->b1 = th.b1;
  hit->b2 = th.b2;
  return true;
}

// Whether every component of the ray's origin and direction is finite (NaN fails every
// comparison; infinities exceed the largest float).
CANDELA_HDI bool isFiniteRay(const Ray& ray) {
  return fabsf(ray.origin.x) <= kInfinity && fabsf(ray.origin.y) <= kInfinity &&
         fabsf(ray.origin.z) <= kInfinity && fabsf(ray.direction.x) <= kInfinity &&
         fabsf(ray.direction.y) <= kInfinity && fabsf(ray.direction.z) <= kInfinity;
}

namespace detail {

// The one traversal loop. anyHit: stop at the first hit not on `skipPrim`; otherwise find the
// nearest hit. Returns whether a hit was found; `hit` receives it (closest mode).
//
// At each 4-wide node all four child boxes are tested together. Leaf children that are hit are
// intersected at once, in slot order, each skipped when a hit found in an earlier one lies
// before its box (docs/performance.md has why they are not sorted); inner children that are hit
// are visited nearest first, the others pushed with their entry distances, so that once a nearer
// hit is known a popped subtree that starts beyond it is skipped without touching its node.
// kMoving: the motion BVH of the step that holds the ray's time (motionNodes from
// motionRoots[step], over motionPrimIndices), its primitives at that time; otherwise the scene's
// BVH. Either up to `tMax`.
template <bool kMoving>
CANDELA_HDI bool traverseBvh(const GeometryView& scene, const Ray& ray, bool anyHit,
                             uint32_t skipPrim, float tMax, Hit* hit) {
  const BvhNode* const nodes = kMoving ? scene.motionNodes : scene.nodes;
  const uint32_t nodeCount = kMoving ? scene.motionNodeCount : scene.nodeCount;
  const uint32_t* const primIndices = kMoving ? scene.motionPrimIndices : scene.primIndices;
  // A ray with a non-finite origin or direction hits nothing: its slab tests could make NaN,
  // which would count every slot of a node as hit, the empty ones (child kNoBvhChild) included.
  // With finite rays an empty slot's box (lo = +inf, hi = -inf) is always missed.
  if (nodeCount == 0 || !isFiniteRay(ray)) return false;
  const RayBoxTester box(
      ray.origin, Vec3(1.0f / ray.direction.x, 1.0f / ray.direction.y, 1.0f / ray.direction.z));
  MotionStep step;
  uint32_t current = 0;
  if constexpr (kMoving) {  // the BVH of the step that holds the ray's time
    step = motionStepAt(scene, ray.time);
    current = scene.motionRoots[step.step];
  }
  bool found = false;
  uint32_t stackNode[kBvhStackSize];
  float stackEntry[kBvhStackSize];
  int stackSize = 0;
  for (;;) {
    CANDELA_DCHECK(current < nodeCount);
    const BvhNode& node = nodes[current];
    float entry[4];
    const int hitMask = box.hit4(node.lo, node.hi, tMax, entry);
    const int leafMask = (node.count[0] != 0) | (node.count[1] != 0) << 1 |
                         (node.count[2] != 0) << 2 | (node.count[3] != 0) << 3;

    // Children are picked from bit masks, not by testing each of the four slots: those tests were
    // the traversal's most mispredicted branches.
    for (int leaves = hitMask & leafMask; leaves != 0; leaves &= leaves - 1) {
      const int c = lowestSetBit(uint32_t(leaves));
      if (entry[c] > tMax) continue;
      for (uint32_t i = 0; i < node.count[c]; ++i) {
        const uint32_t prim = primIndices[node.child[c] + i];
        if (prim == skipPrim) continue;
        if (intersectPrimitive<kMoving>(scene, ray, prim, tMax, hit, step)) {
          if (anyHit) return true;
          found = true;
          tMax = hit->t;  // later candidates must be nearer
        }
      }
    }

    // Inner children still in reach, sorted nearest first (insertion sort of at most four).
    uint32_t next[4];
    float nextEntry[4];
    int nextCount = 0;
    for (int inner = hitMask & ~leafMask; inner != 0; inner &= inner - 1) {
      const int c = lowestSetBit(uint32_t(inner));
      if (entry[c] > tMax) continue;
      int k = nextCount++;
      for (; k > 0 && nextEntry[k - 1] > entry[c]; --k) {
        next[k] = next[k - 1];
        nextEntry[k] = nextEntry[k - 1];
      }
      next[k] = node.child[c];
      nextEntry[k] = entry[c];
    }
    if (nextCount > 0) {
      for (int k = nextCount - 1; k >= 1; --k) {
        CANDELA_DCHECK(stackSize < kBvhStackSize);
        stackNode[stackSize] = next[k];
        stackEntry[stackSize++] = nextEntry[k];
      }
      current = next[0];
      continue;
    }
    // Pop the next subtree that may still hold a nearer hit.
    do {
      if (stackSize == 0) return found;
      current = stackNode[--stackSize];
    } while (stackEntry[stackSize] > tMax);
  }
}

}  // namespace detail

// The moving primitives' part of a query (the motion BVH's; geometry/motion.h), also for an engine
// that traces the others itself; the scene must have a motion BVH (motionNodeCount != 0). Out of
// line on the CPU: scenes where nothing moves keep their traversal as it was. The nearest hit of a
// moving primitive before `tMax`:
CANDELA_HD_CPU_CALL bool intersectClosestMoving(const GeometryView& scene, const Ray& ray,
                                                float tMax, Hit* hit) {
  return detail::traverseBvh<true>(scene, ray, false, 0xffffffffu, tMax, hit);
}

// and whether a moving primitive other than `skipPrim` blocks the ray.
CANDELA_HD_CPU_CALL bool intersectAnyMoving(const GeometryView& scene, const Ray& ray,
                                            uint32_t skipPrim) {
  Hit unused;
  return detail::traverseBvh<true>(scene, ray, true, skipPrim, ray.tMax, &unused);
}

// Nearest hit of `ray` for t in (0, ray.tMax), among the primitives that stand still and then
// those that move (at the ray's time) up to the nearer hit. On a hit fills `hit` and returns true;
// on a miss returns false and leaves `hit` untouched.
CANDELA_HDI bool intersectClosest(const GeometryView& scene, const Ray& ray, Hit* hit) {
  const bool found = detail::traverseBvh<false>(scene, ray, false, 0xffffffffu, ray.tMax, hit);
  if (scene.motionNodeCount == 0) return found;
  return intersectClosestMoving(scene, ray, found ? hit->t : ray.tMax, hit) || found;
}

// Whether anything but primitive `skipPrim` (0xffffffff: none) blocks `ray` for t in
// (0, ray.tMax). Used by shadow rays; a ray towards a point sampled on a sphere light skips
// that light's own sphere.
CANDELA_HDI bool intersectAny(const GeometryView& scene, const Ray& ray, uint32_t skipPrim) {
  Hit unused;
  if (detail::traverseBvh<false>(scene, ray, true, skipPrim, ray.tMax, &unused)) return true;
  return scene.motionNodeCount != 0 && intersectAnyMoving(scene, ray, skipPrim);
}

// Nearest hit by testing every primitive (each where it stands at the ray's time), ignoring the
// BVHs: the reference for tests and benchmarks. Same contract as intersectClosest.
CANDELA_HDI bool intersectClosestBruteForce(const GeometryView& scene, const Ray& ray, Hit* hit) {
  float tMax = ray.tMax;
  bool found = false;
  const MotionStep step = scene.motionTimeCount > 1 ? motionStepAt(scene, ray.time) : MotionStep();
  for (uint32_t prim = 0; prim < scene.primitiveCount(); ++prim) {
    if (intersectPrimitive<true>(scene, ray, prim, tMax, hit, step)) {
      found = true;
      tMax = hit->t;
    }
  }
  return found;
}

// Any-hit by testing every primitive; the reference for intersectAny.
CANDELA_HDI bool intersectAnyBruteForce(const GeometryView& scene, const Ray& ray, uint32_t skipPrim) {
  Hit unused;
  const MotionStep step = scene.motionTimeCount > 1 ? motionStepAt(scene, ray.time) : MotionStep();
  for (uint32_t prim = 0; prim < scene.primitiveCount(); ++prim)
    if (prim != skipPrim && intersectPrimitive<true>(scene, ray, prim, ray.tMax, &unused, step))
      return true;
  return false;
}

}  // namespace candela
