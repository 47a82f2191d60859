// collapseToWide: binary BVH -> 4-wide BVH (see bvh_build.h).
//
// Each wide node gathers up to four subtrees of the binary tree: starting from a binary inner
// node's two children, the inner child with the largest surface area is replaced by its own two
// children until four are gathered or only leaves remain. Opening the largest boxes first keeps
// the wide node's children as small as possible, which is what a ray's box tests pay for. Wide
// nodes are emitted depth-first; binary leaves become leaf slots.
#include <cstring>
#include <limits>

#include "geometry/aabb.h"
#include "geometry/bvh_build.h"

namespace candela {

static_assert(kBvhMaxLeafSize <= 255, "leaf sizes must fit BvhNode::count");

namespace {

Bounds3 boundsOf(const BinaryBvhNode& n) { return Bounds3(n.boundsMin, n.boundsMax); }

class Collapser {
 public:
  Collapser(const BinaryBvhNode* binary, std::vector<BvhNode>& wide)
      : binary_(binary), wide_(wide) {}

  // Emits the wide node holding the subtrees below binary node `root` (or `root` itself when it
  // is a leaf, as in a one-leaf tree) and returns its index.
  uint32_t emit(uint32_t root) {
    uint32_t children[4];
    int childCount = 0;
    if (binary_[root].primCount > 0) {
      children[childCount++] = root;
    } else {
      children[childCount++] = root + 1;
      children[childCount++] = binary_[root].offset;
      while (childCount < 4) {
        int widest = -1;
        float widestArea = -1.0f;
        for (int i = 0; i < childCount; ++i) {
          const BinaryBvhNode& n = binary_[children[i]];
          const float area = boundsOf(n).surfaceArea();
          if (n.primCount == 0 && area > widestArea) widest = i, widestArea = area;
        }
        if (widest < 0) break;
        const uint32_t opened = children[widest];
        children[widest] = opened + 1;
        children[childCount++] = binary_[opened].offset;
      }
    }

    const uint32_t index = static_cast<uint32_t>(wide_.size());
    wide_.push_back(emptyBvhNode());
    for (int i = 0; i < childCount; ++i) {
      const BinaryBvhNode& n = binary_[children[i]];
      uint32_t child;
      uint8_t count;
      if (n.primCount > 0) {
        child = n.offset;
        count = static_cast<uint8_t>(n.primCount);
      } else {
        child = emit(children[i]);  // may reallocate wide_: index, not reference, below
        count = 0;
      }
      BvhNode& w = wide_[index];
      for (int axis = 0; axis < 3; ++axis) {
        w.lo[axis][i] = n.boundsMin[axis];
        w.hi[axis][i] = n.boundsMax[axis];
      }
      w.child[i] = child;
      w.count[i] = count;
    }
    return index;
  }

 private:
  const BinaryBvhNode* binary_;
  std::vector<BvhNode>& wide_;
};

}  // namespace

std::vector<BvhNode> collapseToWide(const BinaryBvhNode* binary, uint32_t nodeCount) {
  std::vector<BvhNode> wide;
  if (nodeCount == 0) return wide;
  wide.reserve(nodeCount / 3 + 1);
  Collapser(binary, wide).emit(0);
  return wide;
}

}  // namespace candela
