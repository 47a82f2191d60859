// Bounding boxes of the scene's primitives, shared by the BVH build and the refit.
#pragma once

#include <vector>

#include "core/float_error.h"
#include "geometry/aabb.h"
#include "geometry/geometry_view.h"
#include "geometry/motion.h"
#include "geometry/shapes.h"

namespace candela {

// Rounded outwards: the box must contain the sphere, not just the rounded extremes.
inline Bounds3 sphereBounds(const Sphere& s) {
  Bounds3 b(s.center - Vec3(s.radius), s.center + Vec3(s.radius));
  for (int i = 0; i < 3; ++i) {
    b.lo[i] = nextFloatDown(b.lo[i]);
    b.hi[i] = nextFloatUp(b.hi[i]);
  }
  return b;
}

inline Bounds3 triangleBounds(const Vec3* positions, const Triangle& t) {
  Bounds3 b(positions[t.v[0]]);
  b.grow(positions[t.v[1]]);
  b.grow(positions[t.v[2]]);
  return b;
}

// Bounds of primitive p in GeometryView numbering (spheres first, then triangles).
inline Bounds3 primitiveBounds(uint32_t p, const Sphere* spheres, uint32_t sphereCount,
                               const Vec3* positions, const Triangle* triangles) {
  return p < sphereCount ? sphereBounds(spheres[p])
                         : triangleBounds(positions, triangles[p - sphereCount]);
}

// The box of primitive p (GeometryView numbering) over step k of its motion, from pose k to pose
// k + 1 (geometry/motion.h), or where it stands: between two poses each vertex moves on a line,
// which the two poses' boxes hold.
inline Bounds3 stepBounds(const GeometryView& scene, uint32_t p, uint32_t k) {
  if (p < scene.sphereCount) {
    if (!sphereMoves(scene, p)) return sphereBounds(scene.spheres[p]);
    const Sphere* poses = scene.motionSpheres + scene.sphereMotions[p] + k;
    Bounds3 b = sphereBounds(poses[0]);
    b.grow(sphereBounds(poses[1]));
    return b;
  }
  const Triangle& t = scene.triangles[p - scene.sphereCount];
  if (!triangleMoves(scene, t)) return triangleBounds(scene.positions, t);
  Bounds3 b(scene.motionPositions[scene.vertexMotions[t.v[0]] + k]);
  for (uint32_t pose = k; pose <= k + 1; ++pose)
    for (int c = 0; c < 3; ++c) b.grow(scene.motionPositions[scene.vertexMotions[t.v[c]] + pose]);
  return b;
}

// The box of primitive p (GeometryView numbering) over the whole exposure: every step's, or where
// it stands.
inline Bounds3 sweptBounds(const GeometryView& scene, uint32_t p) {
  Bounds3 b = stepBounds(scene, p, 0);
  for (uint32_t k = 1; k + 1 < scene.motionTimeCount; ++k) b.grow(stepBounds(scene, p, k));
  return b;
}

// The primitives of `scene` that move (`moving`) or stand still, appended to *prims, and their
// boxes (stepBounds over step k) to *boxes: what a BVH over one part of the scene is built from.
inline void partBoxes(const GeometryView& scene, bool moving, uint32_t k,
                      std::vector<Bounds3>* boxes, std::vector<uint32_t>* prims) {
  for (uint32_t p = 0; p < scene.primitiveCount(); ++p) {
    const bool moves = p < scene.sphereCount
                           ? sphereMoves(scene, p)
                           : triangleMoves(scene, scene.triangles[p - scene.sphereCount]);
    if (moves != moving) continue;
    boxes->push_back(stepBounds(scene, p, k));
    prims->push_back(p);
  }
}

}  // namespace candela
