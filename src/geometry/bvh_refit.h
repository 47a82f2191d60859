// Refitting a 4-wide BVH after its primitives moved, and the SAH costs that say when a refit
// tree has degraded enough to be rebuilt instead.
//
// A refit keeps the tree's structure (which primitives share leaves, which leaves share nodes)
// and recomputes every box bottom-up from the primitives' new bounds, in linear time. It is exact
// (every ray finds the same nearest hit as with a rebuilt tree) but the tree's quality drops as
// primitives move far from where the build grouped them; bvhCostGrowth measures that.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/bvh_node.h"
#include "geometry/shapes.h"

namespace candela {

// Recomputes all boxes of `nodes` (depth-first: children after parents) for primitives that kept
// their numbering but may have moved.
void refitBvh(std::vector<BvhNode>& nodes, const std::vector<uint32_t>& primIndices,
              const Sphere* spheres, uint32_t sphereCount, const Vec3* positions,
              const Triangle* triangles);

// The costs a refit is judged by: the expected cost of a random ray through a part of the tree by
// the surface area heuristic (one unit per inner box tested, one per primitive in a leaf box
// hit), relative to the part's box, for the whole tree and for each part that holds at least
// 1/16 of its primitives, a part being any two or more of one node's slots with all below them.
// The whole tree's cost alone would not do: where one primitive's box dwarfs the rest (a ground
// sphere of radius 1000 beside two meshes at the root), random rays through the root seldom reach
// the rest, and the root's cost barely moves however the meshes' boxes come to overlap; the
// root's slots but the sphere's are a part whose cost shows it.
struct BvhCostProfile {
  struct Part {
    uint32_t node = 0;
    uint8_t slots = 0;  // a bit per slot of the node
    double cost = 0;
  };
  std::vector<Part> parts;  // the whole tree's first
};
BvhCostProfile bvhCostProfile(const std::vector<BvhNode>& nodes);
// How much a refit has degraded the tree `built` profiled (`nodes` is that tree, refitted): the
// largest ratio of a profiled part's cost now to its cost then. 1 for an empty tree.
double bvhCostGrowth(const std::vector<BvhNode>& nodes, const BvhCostProfile& built);

}  // namespace candela
