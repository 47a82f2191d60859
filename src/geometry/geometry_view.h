// GeometryView: the flat, trivially copyable geometry that traversal and surface reconstruction
// read: arrays of plain structs + counts, pointing into host memory on the CPU and into device
// buffers on CUDA.
//
// Conventions:
// - World space is right-handed, +y up. Mesh vertices are already transformed to world space.
// - `normals` is empty or parallel to `positions`: normals[i] is vertex i's shading normal,
//   octahedrally encoded (core/oct_normal.h); "none" makes a triangle with such a vertex use its
//   face normal.
// - `uvs` is empty or parallel to `positions` (texture coordinates, (0, 0) for vertices of meshes
//   without any). The texture pool (core/texture.h) lives here too, since alpha tests during
//   traversal read it; `alphaMasks` is empty when no material is masked, else one per material.
// - Primitive index p in [0, sphereCount) is spheres[p]; p >= sphereCount is triangle
//   p - sphereCount. The BVH leaves index `primIndices`, which hold such primitive indices.
// - Primitives that move while the shutter is open (motion blur: geometry/motion.h) are left out
//   of that BVH and kept in BVHs of their own, one for each step k between two of their poses,
//   whose boxes hold each primitive's sweep over that step: its root is
//   motionNodes[motionRoots[k]], its leaves index motionPrimIndices. Their arrays above hold them
//   at the frame's time; at `motionTimes` (increasing from 0, the shutter's opening, to 1, its
//   closing) a moving vertex v is at motionPositions[vertexMotions[v] + k] (with motionNormals
//   parallel, where there are normals), a moving sphere s is motionSpheres[sphereMotions[s] + k];
//   kStill marks the others. All are empty in a scene where nothing moves.
#pragma once

#include <cstdint>
#include <type_traits>

#include "core/device.h"
#include "core/oct_normal.h"
#include "core/texture.h"
#include "core/vec2.h"
#include "core/vec3.h"
#include "geometry/alpha_mask.h"
#include "geometry/bvh_node.h"
#include "geometry/shapes.h"

namespace candela {

// Every geometry array, as X(Type, name, count, rewrittenBy): the one list that the views, the
// owning SceneData and the CUDA upload expand, so an array is added in one place. rewrittenBy is
// what may rewrite the array (RewrittenBy, render/scene_change.h): Values for what any frame may
// change (the alpha masks follow the materials), Motion for what moving primitives change (a
// refit), Structure for what only a rebuild changes, TexturePool for the pool, which changes with
// the textures' contents alone (frames that keep them keep it, across rebuilds too).
#define CANDELA_GEOMETRY_ARRAYS(X)                          \
  X(Sphere, spheres, sphereCount, Motion)                   \
  X(Vec3, positions, positionCount, Motion)                 \
  X(OctNormal, normals, normalCount, Motion)                \
  X(Vec2, uvs, uvCount, Structure)                          \
  X(Triangle, triangles, triangleCount, Structure)          \
  X(BvhNode, nodes, nodeCount, Motion)                      \
  X(uint32_t, primIndices, primIndexCount, Structure)       \
  X(AlphaMask, alphaMasks, alphaMaskCount, Values)          \
  X(Texture, textures, textureCount, TexturePool)           \
  X(uint8_t, texels8, texel8Count, TexturePool)             \
  X(float, texelsF, texelFCount, TexturePool)               \
  X(float, srgbToLinear, srgbToLinearCount, TexturePool)    \
  X(float, motionTimes, motionTimeCount, Structure)         \
  X(uint32_t, vertexMotions, vertexMotionCount, Structure)  \
  X(Vec3, motionPositions, motionPositionCount, Structure)  \
  X(OctNormal, motionNormals, motionNormalCount, Structure) \
  X(uint32_t, sphereMotions, sphereMotionCount, Structure)  \
  X(Sphere, motionSpheres, motionSphereCount, Structure)    \
  X(BvhNode, motionNodes, motionNodeCount, Structure)       \
  X(uint32_t, motionRoots, motionRootCount, Structure)      \
  X(uint32_t, motionPrimIndices, motionPrimIndexCount, Structure)

#define CANDELA_VIEW_ARRAY_FIELDS(Type, name, count, rewrittenBy) \
  const Type* name = nullptr;                                     \
  uint32_t count = 0;

struct GeometryView {
  CANDELA_GEOMETRY_ARRAYS(CANDELA_VIEW_ARRAY_FIELDS)

  CANDELA_HDI uint32_t primitiveCount() const { return sphereCount + triangleCount; }
  CANDELA_HDI TexturePool texturePool() const {
    return {textures, texels8, texelsF, srgbToLinear};
  }
};
static_assert(std::is_trivially_copyable<GeometryView>::value,
              "GeometryView must be trivially copyable");

}  // namespace candela
