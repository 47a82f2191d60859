// Host-side BVH construction over the scene's spheres and triangles.
//
// Binned surface-area-heuristic build (pbrt-v4's aggregates.cpp, Wald 2007): at each node the
// primitive centroids are binned along all three axes and the cheapest split plane is taken; a
// node becomes a leaf when the SAH prefers it and it holds at most kBvhMaxLeafSize primitives.
// The binary tree is laid out depth-first in 32-byte BinaryBvhNode records (an interior node's
// first child follows it, `offset` names the second), then collapsed into the 4-wide BvhNode
// records the renderer traverses (geometry/bvh_node.h), which is all the build returns.
//
// Primitive indices follow GeometryView's convention: p < sphereCount is a sphere, else triangle
// p - sphereCount. An empty scene yields zero nodes (a leaf cannot be empty: primCount 0 marks an
// interior node); traversal reports a miss for a scene without nodes.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "geometry/aabb.h"
#include "geometry/bvh_node.h"
#include "geometry/shapes.h"

namespace candela {

// Node of the binary tree the SAH build makes, depth-first: an interior node's first child
// follows it. Leaves hold primCount > 0 primitives from primIndices[offset]. The build lays
// subtrees out with gaps between them (see bvh_build.cpp), so only the links, not the count of
// records, describe the tree.
struct BinaryBvhNode {
  Vec3 boundsMin;
  uint32_t offset;  // leaf: first index into primIndices; interior: index of the second child
  Vec3 boundsMax;
  uint16_t primCount;  // 0 for interior nodes
  uint8_t axis;        // interior: split axis
  uint8_t pad;
};
static_assert(sizeof(BinaryBvhNode) == 32, "BinaryBvhNode must stay 32 bytes");

// Leaves hold at most this many primitives.
constexpr uint32_t kBvhMaxLeafSize = 4;
// Depth bound of every tree buildBvh returns (and so of its 4-wide form).
constexpr uint32_t kBvhMaxDepth = 63;

struct BvhBuildResult {
  std::vector<BvhNode> wideNodes;     // depth-first, wideNodes[0] the root: what the renderer uses
  std::vector<uint32_t> primIndices;  // leaf ranges index this; a permutation of all primitives
  uint32_t leafCount = 0;   // of the binary tree; each is one leaf slot of the wide nodes
  uint32_t maxDepth = 0;    // of the binary tree's deepest leaf (the root has depth 0); the
                            // wide tree is at most as deep
  double buildSeconds = 0;  // wall time of buildBvh
};

// Collapses the binary tree rooted at binary[0], of nodeCount nodes, into 4-wide nodes: each
// wide node takes the up to four descendants reached by repeatedly opening the inner child of
// largest surface area. Empty for an empty tree.
std::vector<BvhNode> collapseToWide(const BinaryBvhNode* binary, uint32_t nodeCount);

// Builds the BVH of sphereCount spheres and triangleCount triangles (vertex indices into
// positions), returning its 4-wide form. Uses all cores through oneTBB for large scenes; the
// result does not depend on the thread count.
BvhBuildResult buildBvh(const Sphere* spheres, uint32_t sphereCount, const Vec3* positions,
                        const Triangle* triangles, uint32_t triangleCount);

// Builds the BVH of `count` primitives of given boxes: primitive prims[i] (GeometryView numbering)
// in boxes[i]. For a part of a scene's primitives (those that stand still, or those that move,
// each in its box over one step of its motion: geometry/primitive_bounds.h, partBoxes).
BvhBuildResult buildBvhOfBoxes(const Bounds3* boxes, const uint32_t* prims, uint32_t count);

// A tree of one level for benchmarks that measure what the BVH buys: a chain of nodes whose
// slots are leaves of up to 255 primitives, every box the bounds of the whole scene, so every ray
// that enters the scene is tested against every primitive. Traversal and refit need no special
// case for it.
BvhBuildResult buildFlatBvh(const Sphere* spheres, uint32_t sphereCount, const Vec3* positions,
                            const Triangle* triangles, uint32_t triangleCount);

}  // namespace candela
