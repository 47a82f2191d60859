// The one-level "BVH" of buildFlatBvh; see bvh_build.h.
#include <algorithm>
#include <chrono>
#include <numeric>

#include "geometry/aabb.h"
#include "geometry/bvh_build.h"
#include "geometry/primitive_bounds.h"

namespace candela {

BvhBuildResult buildFlatBvh(const Sphere* spheres, uint32_t sphereCount, const Vec3* positions,
                            const Triangle* triangles, uint32_t triangleCount) {
  const auto start = std::chrono::steady_clock::now();
  const uint32_t count = sphereCount + triangleCount;
  BvhBuildResult result;
  result.primIndices.resize(count);
  std::iota(result.primIndices.begin(), result.primIndices.end(), 0u);
  Bounds3 scene;
  for (uint32_t p = 0; p < count; ++p)
    scene.grow(primitiveBounds(p, spheres, sphereCount, positions, triangles));

  // Slots 0-2 of each node are leaves, slot 3 the next node of the chain.
  constexpr uint32_t kLeafSize = 255, kLeavesPerNode = 3;
  const auto setBox = [&scene](BvhNode& node, int slot) {
    for (int axis = 0; axis < 3; ++axis) {
      node.lo[axis][slot] = scene.lo[axis];
      node.hi[axis][slot] = scene.hi[axis];
    }
  };
  for (uint32_t first = 0; first < count; first += kLeafSize * kLeavesPerNode) {
    BvhNode node = emptyBvhNode();
    for (uint32_t slot = 0; slot < kLeavesPerNode; ++slot) {
      const uint32_t begin = first + slot * kLeafSize;
      if (begin >= count) break;
      node.child[slot] = begin;
      node.count[slot] = uint8_t(std::min(kLeafSize, count - begin));
      setBox(node, int(slot));
      ++result.leafCount;
    }
    if (first + kLeafSize * kLeavesPerNode < count) {
      node.child[3] = uint32_t(result.wideNodes.size() + 1);
      setBox(node, 3);
    }
    result.wideNodes.push_back(node);
  }
  result.maxDepth = uint32_t(result.wideNodes.size());
  result.buildSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace candela
