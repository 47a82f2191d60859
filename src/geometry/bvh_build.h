// Host-side BVH construction over the scene's spheres and triangles.
//
// Binned surface-area-heuristic build (pbrt-v4's aggregates.cpp, Wald 2007): at each node the
// primitive centroids are binned along all three axes and the cheapest split plane is taken; a
// node becomes a leaf when the SAH prefers it and it holds at most kBvhMaxLeafSize primitives.
// The tree is flattened depth-first into 32-byte BvhNode records (scene/scene_view.h): an
// interior node's first child follows it, `offset` names the second.
//
// Primitive indices follow SceneView's convention: p < sphereCount is a sphere, else triangle
// p - sphereCount. An empty scene yields zero nodes (a leaf cannot be empty: primCount 0 marks an
// interior node); traversal reports a miss for a scene without nodes.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "scene/scene_view.h"

namespace candela {

// Leaves hold at most this many primitives.
constexpr uint32_t kBvhMaxLeafSize = 4;
// Depth bound of every tree buildBvh returns; traversal stacks of 64 entries never overflow.
constexpr uint32_t kBvhMaxDepth = 63;

struct BvhBuildResult {
  std::vector<BvhNode> nodes;         // depth-first; nodes[0] is the root when not empty
  std::vector<uint32_t> primIndices;  // leaf ranges index this; a permutation of all primitives
  uint32_t leafCount = 0;
  uint32_t maxDepth = 0;    // depth of the deepest leaf; the root has depth 0
  double buildSeconds = 0;  // wall time of buildBvh
};

// Builds the BVH of sphereCount spheres and triangleCount triangles (vertex indices into
// positions). Uses all cores through oneTBB for large scenes; the result does not depend on the
// thread count.
BvhBuildResult buildBvh(const Sphere* spheres, uint32_t sphereCount, const Vec3* positions,
                        const Triangle* triangles, uint32_t triangleCount);

}  // namespace candela
