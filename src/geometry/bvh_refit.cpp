#include "geometry/bvh_refit.h"

#include <algorithm>

#include "geometry/aabb.h"
#include "geometry/primitive_bounds.h"

namespace candela {
namespace {

Bounds3 slotBounds(const BvhNode& n, int c) {
  return Bounds3(Vec3(n.lo[0][c], n.lo[1][c], n.lo[2][c]), Vec3(n.hi[0][c], n.hi[1][c], n.hi[2][c]));
}

Bounds3 nodeBounds(const BvhNode& n) {
  Bounds3 b;
  for (int c = 0; c < 4; ++c)
    if (n.count[c] > 0 || n.child[c] != kNoBvhChild) b.grow(slotBounds(n, c));
  return b;
}

// Each node's subtree: its primitives, and its SAH cost times its box's area (the sum over its
// boxes of area times primitives, or times one for an inner box).
struct SubtreeSums {
  std::vector<uint64_t> primitives;
  std::vector<double> weightedArea;
};

SubtreeSums subtreeSums(const std::vector<BvhNode>& nodes) {
  SubtreeSums sums{std::vector<uint64_t>(nodes.size(), 0), std::vector<double>(nodes.size(), 0.0)};
  // Reverse depth-first order visits every child node before its parent.
  for (size_t i = nodes.size(); i-- > 0;) {
    const BvhNode& node = nodes[i];
    for (int c = 0; c < 4; ++c) {
      const double area = slotBounds(node, c).surfaceArea();
      if (node.count[c] > 0) {
        sums.primitives[i] += node.count[c];
        sums.weightedArea[i] += area * double(node.count[c]);
      } else if (node.child[c] != kNoBvhChild) {
        sums.primitives[i] += sums.primitives[node.child[c]];
        sums.weightedArea[i] += area + sums.weightedArea[node.child[c]];
      }
    }
  }
  return sums;
}

// The cost of the part of `node` made of the slots of `mask` (bit c: slot c), relative to its
// box; 0 where that box has no area.
double partCost(const std::vector<BvhNode>& nodes, const SubtreeSums& sums, uint32_t node,
                uint32_t mask) {
  const BvhNode& n = nodes[node];
  Bounds3 box;
  double weightedArea = 0.0;
  for (int c = 0; c < 4; ++c) {
    if (!(mask >> c & 1u)) continue;
    const Bounds3 slot = slotBounds(n, c);
    box.grow(slot);
    weightedArea += n.count[c] > 0 ? slot.surfaceArea() * double(n.count[c])
                                   : slot.surfaceArea() + sums.weightedArea[n.child[c]];
  }
  const double area = box.surfaceArea();
  return area > 0.0 ? weightedArea / area : 0.0;
}

}  // namespace

void refitBvh(std::vector<BvhNode>& nodes, const std::vector<uint32_t>& primIndices,
              const Sphere* spheres, uint32_t sphereCount, const Vec3* positions,
              const Triangle* triangles) {
  // Reverse depth-first order visits every child node before its parent.
  for (size_t i = nodes.size(); i-- > 0;) {
    BvhNode& node = nodes[i];
    for (int c = 0; c < 4; ++c) {
      Bounds3 b;
      if (node.count[c] > 0) {
        for (uint32_t k = 0; k < node.count[c]; ++k)
          b.grow(primitiveBounds(primIndices[node.child[c] + k], spheres, sphereCount, positions,
                                 triangles));
      } else if (node.child[c] != kNoBvhChild) {
        b = nodeBounds(nodes[node.child[c]]);
      } else {
        continue;  // unused slot: keeps its empty box
      }
      for (int axis = 0; axis < 3; ++axis) {
        node.lo[axis][c] = b.lo[axis];
        node.hi[axis][c] = b.hi[axis];
      }
    }
  }
}

BvhCostProfile bvhCostProfile(const std::vector<BvhNode>& nodes) {
  BvhCostProfile profile;
  if (nodes.empty()) return profile;
  const SubtreeSums sums = subtreeSums(nodes);
  const uint64_t large = std::max<uint64_t>(1, sums.primitives[0] / 16);
  for (uint32_t i = 0; i < nodes.size(); ++i) {
    if (i > 0 && sums.primitives[i] < large) continue;  // and so is every part of it
    const BvhNode& n = nodes[i];
    uint32_t used = 0;
    uint64_t slotPrimitives[4] = {};
    for (int c = 0; c < 4; ++c) {
      if (n.count[c] > 0) {
        slotPrimitives[c] = n.count[c];
      } else if (n.child[c] != kNoBvhChild) {
        slotPrimitives[c] = sums.primitives[n.child[c]];
      } else {
        continue;
      }
      used |= 1u << c;
    }
    // The whole tree first, then every part of two or more slots that is large enough.
    if (i == 0) profile.parts.push_back({0, uint8_t(used), partCost(nodes, sums, 0, used)});
    for (uint32_t mask = 1; mask < 16; ++mask) {
      if ((mask & used) != mask || (mask & (mask - 1)) == 0 || (i == 0 && mask == used)) continue;
      uint64_t primitives = 0;
      for (int c = 0; c < 4; ++c)
        if (mask >> c & 1u) primitives += slotPrimitives[c];
      if (primitives >= large)
        profile.parts.push_back({i, uint8_t(mask), partCost(nodes, sums, i, mask)});
    }
  }
  return profile;
}

double bvhCostGrowth(const std::vector<BvhNode>& nodes, const BvhCostProfile& built) {
  if (nodes.empty()) return 1.0;
  const SubtreeSums sums = subtreeSums(nodes);
  double growth = 1.0;
  for (const BvhCostProfile::Part& part : built.parts)
    if (part.cost > 0.0)
      growth = std::max(growth, partCost(nodes, sums, part.node, part.slots) / part.cost);
  return growth;
}

}  // namespace candela
