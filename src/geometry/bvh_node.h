// Node of the 4-wide BVH the renderer traverses, 128 bytes (two cache lines).
//
// It holds the boxes of up to four children side by side, one array per axis, so that one visit
// tests four boxes in a loop the compiler turns into vector instructions. nodes[0] is the root.
// Child slot i: count[i] == 0 and child[i] a node index for an inner child; count[i] > 0 for a
// leaf of count[i] primitives from primIndices[child[i]]; an unused slot has an empty box
// (lo = +inf, hi = -inf), which no ray hits, and count 0, child kNoBvhChild.
#pragma once

#include <cstdint>
#include <cstring>
#include <limits>

namespace candela {

struct BvhNode {
  float lo[3][4];  // [axis][child]
  float hi[3][4];
  uint32_t child[4];
  uint8_t count[4];
  uint32_t pad[3];
};
static_assert(sizeof(BvhNode) == 128, "BvhNode must stay 128 bytes");
constexpr uint32_t kNoBvhChild = 0xffffffffu;

// A node whose four slots are all unused; the builders fill slots in from this.
inline BvhNode emptyBvhNode() {
  BvhNode node;
  const float inf = std::numeric_limits<float>::infinity();
  for (int axis = 0; axis < 3; ++axis)
    for (int c = 0; c < 4; ++c) {
      node.lo[axis][c] = inf;
      node.hi[axis][c] = -inf;
    }
  for (int c = 0; c < 4; ++c) {
    node.child[c] = kNoBvhChild;
    node.count[c] = 0;
  }
  std::memset(node.pad, 0, sizeof node.pad);
  return node;
}

}  // namespace candela
