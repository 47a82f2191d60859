// SphereBlocks: a scene's spheres, when they are few, tested four at a time with SSE instead of
// through a BVH; the Embree engine's sphere part (backends/cpu/embree_tracer.h).
//
// The room scenes' walls are huge overlapping spheres whose boxes every ray enters, so a sphere
// BVH tests them all anyway, one by one, behind branches a CPU mispredicts (they were 45% of the
// default room's time). Here each block of four is one straight-line test, the operations those
// of intersectSphere (geometry/sphere_intersect.h) in the same order and without contraction, so
// a hit's t is bit-identical to the own BVH engine's. Of two spheres hit at exactly the same t
// the lower index wins, where the BVH's visiting order decides; only coincident spheres differ.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/ray.h"
#include "geometry/shapes.h"

namespace candela {

// Up to this many spheres are tested in blocks; more get a BVH.
constexpr uint32_t kSphereBlocksUpTo = 32;

// Structure of arrays, padded to a multiple of four with spheres no ray hits.
struct SphereBlocksView {
  const float* centerX = nullptr;
  const float* centerY = nullptr;
  const float* centerZ = nullptr;
  const float* radius = nullptr;
  const float* radiusSquared = nullptr;
  uint32_t blockCount = 0;
};

class SphereBlocks {
 public:
  void assign(const Sphere* spheres, uint32_t count);
  SphereBlocksView view() const;
  size_t bytes() const { return data_.size() * sizeof(float); }

 private:
  std::vector<float> data_;  // five arrays of 4 * blockCount_ floats, one after the other
  uint32_t blockCount_ = 0;
};

// Nearest sphere hit for t in (0, tMax); on a hit sets *t and *prim and returns true.
bool closestSphere(const SphereBlocksView& blocks, const Ray& ray, float tMax, float* t,
                   uint32_t* prim);
// Whether a sphere other than `skipPrim` is hit for t in (0, ray.tMax).
bool anySphere(const SphereBlocksView& blocks, const Ray& ray, uint32_t skipPrim);

}  // namespace candela
