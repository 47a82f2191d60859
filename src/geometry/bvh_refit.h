// Refitting a 4-wide BVH after its primitives moved, and the SAH cost that says when a refit
// tree has degraded enough to be rebuilt instead.
//
// A refit keeps the tree's structure (which primitives share leaves, which leaves share nodes)
// and recomputes every box bottom-up from the primitives' new bounds, in linear time. It is exact
// (every ray finds the same nearest hit as with a rebuilt tree) but the tree's quality drops as
// primitives move far from where the build grouped them; bvhSahCost measures that.
#pragma once

#include <vector>

#include "geometry/bvh_node.h"
#include "geometry/shapes.h"

namespace candela {

// Recomputes all boxes of `nodes` (depth-first: children after parents) for primitives that kept
// their numbering but may have moved.
void refitBvh(std::vector<BvhNode>& nodes, const std::vector<uint32_t>& primIndices,
              const Sphere* spheres, uint32_t sphereCount, const Vec3* positions,
              const Triangle* triangles);

// Expected cost of a random ray by the surface area heuristic, relative to the root box:
// one unit per inner box tested, one per primitive in a leaf box hit. 0 for an empty tree.
double bvhSahCost(const std::vector<BvhNode>& nodes);

}  // namespace candela
