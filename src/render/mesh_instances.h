// Objects that repeat one mesh, as flattening found them: host only, for a ray engine that traces
// such objects as instances of one structure (backends/cpu/embree_scene.cpp) rather than as
// triangles of their own. The kernel never reads these: every object's triangles are in the
// scene's arrays, in world space, whatever the engine does.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mat3.h"
#include "core/padded_allocator.h"
#include "core/vec3.h"

namespace candela {

// Where an object's triangles and vertices lie in the scene's arrays (in file order: valid only
// while no own BVH has reordered the triangles), and where it stands.
struct MeshInstance {
  uint32_t firstTriangle = 0, triangleCount = 0;
  uint32_t firstVertex = 0, vertexCount = 0;
  // Object to world: p' = translation + linear p, as flattening placed the vertices (up to
  // rounding).
  Mat3 linear;
  Vec3 translation;
  // The MeshPrototype this object repeats (-1: its mesh is its own). Instances of one prototype
  // have the same triangles, up to a shift of their vertex indices by firstVertex.
  int32_t prototype = -1;
  // Whether it moves while the shutter is open: its triangles are the motion BVH's
  // (geometry/motion.h), not the engine's.
  bool moves = false;
};

// A mesh that several objects repeat.
struct MeshPrototype {
  // Object space, in the order of each instance's vertices (firstVertex on): an instance's
  // vertex k is linear * positions[k] + translation.
  PaddedVector<Vec3> positions;  // padded: Embree shares them
  uint32_t firstInstance = 0;  // the first object that repeats it: its triangles are the pattern
  uint32_t instanceCount = 0;
};

struct MeshInstances {
  std::vector<MeshInstance> objects;  // one per object, in file order; empty where invalid
  std::vector<MeshPrototype> prototypes;
};

}  // namespace candela
