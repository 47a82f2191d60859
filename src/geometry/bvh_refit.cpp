#include "geometry/bvh_refit.h"

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

double bvhSahCost(const std::vector<BvhNode>& nodes) {
  if (nodes.empty()) return 0.0;
  const double rootArea = nodeBounds(nodes[0]).surfaceArea();
  if (!(rootArea > 0.0)) return 0.0;
  double cost = 0.0;
  for (const BvhNode& node : nodes)
    for (int c = 0; c < 4; ++c) {
      if (node.count[c] == 0 && node.child[c] == kNoBvhChild) continue;
      const double area = slotBounds(node, c).surfaceArea();
      cost += area * (node.count[c] > 0 ? double(node.count[c]) : 1.0);
    }
  return cost / rootArea;
}

}  // namespace candela
