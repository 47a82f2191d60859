// SphereBlocks: a scene's spheres, when they are few, tested a block at a time with SIMD instead
// of through a BVH; the Embree engine's sphere part (backends/cpu/embree_tracer.h).
//
// The room scenes' walls are huge overlapping spheres whose boxes every ray enters, so a sphere
// BVH tests them all anyway, one by one, behind branches a CPU mispredicts (they were 45% of the
// default room's time). Here each block is one straight-line test, the operations those of
// intersectSphere (geometry/sphere_intersect.h) in the same order and without contraction, so a
// hit's t is bit-identical to the own BVH engine's, at every block width. Of two spheres hit at
// exactly the same t the lower index wins, where the BVH's visiting order decides; only
// coincident spheres differ.
//
// A block is 4 spheres wide (SSE2) or 8 (AVX2, where the CPU has it, chosen at run time): with the
// room's six walls in one block of 8, a ray takes one block's full test where blocks of 4 took
// two (docs/performance.md, "Spheres in blocks"). Blocks of 16 (AVX-512) measured slower than
// two of 8 on an AMD EPYC, whose AVX-512 units are 256 bits wide.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/ray.h"
#include "geometry/shapes.h"

namespace candela {

// Up to this many spheres are tested in blocks; more get a BVH.
constexpr uint32_t kSphereBlocksUpTo = 32;

// Structure of arrays, padded to a multiple of `width` with spheres no ray hits.
struct SphereBlocksView {
  const float* centerX = nullptr;
  const float* centerY = nullptr;
  const float* centerZ = nullptr;
  const float* radius = nullptr;
  const float* radiusSquared = nullptr;
  uint32_t blockCount = 0;
  uint32_t width = 4;  // spheres per block: 4 or 8
};

// The widest block this CPU tests: 8 with AVX2, else 4.
uint32_t widestSphereBlock();

class SphereBlocks {
 public:
  // Blocks of at most `maxWidth` spheres (a width the CPU has; tests choose one). Where `motions`
  // (GeometryView::sphereMotions, or null) says a sphere moves, its lane is a blank no ray hits:
  // the motion BVH holds it (geometry/motion.h).
  void assign(const Sphere* spheres, uint32_t count, uint32_t maxWidth = widestSphereBlock(),
              const uint32_t* motions = nullptr);
  SphereBlocksView view() const;
  size_t bytes() const { return data_.size() * sizeof(float); }

 private:
  std::vector<float> data_;  // five arrays of width_ * blockCount_ floats, one after the other
  uint32_t blockCount_ = 0;
  uint32_t width_ = 4;
};

// Nearest sphere hit for t in (0, tMax); on a hit sets *t and *prim and returns true.
bool closestSphere(const SphereBlocksView& blocks, const Ray& ray, float tMax, float* t,
                   uint32_t* prim);
// Whether a sphere other than `skipPrim` is hit for t in (0, ray.tMax).
bool anySphere(const SphereBlocksView& blocks, const Ray& ray, uint32_t skipPrim);

// The two tests at each block width, each compiled for its instruction set (sphere_blocks_w*.cpp);
// closestSphere and anySphere call those of the view's width.
bool closestSphereW4(const SphereBlocksView&, const Ray&, float tMax, float* t, uint32_t* prim);
bool closestSphereW8(const SphereBlocksView&, const Ray&, float tMax, float* t, uint32_t* prim);
bool anySphereW4(const SphereBlocksView&, const Ray&, uint32_t skipPrim);
bool anySphereW8(const SphereBlocksView&, const Ray&, uint32_t skipPrim);

}  // namespace candela
