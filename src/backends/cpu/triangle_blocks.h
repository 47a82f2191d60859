// TriangleBlocks: a scene's triangles, when they are very few, tested a block at a time with SIMD
// instead of through Embree's BVH; the Embree engine's triangle part for such scenes
// (backends/cpu/embree_tracer.h).
//
// In a box of a few dozen triangles (the Cornell box's 32) nearly every ray enters the boxes of
// most leaves, so a BVH walk is mostly overhead; all of them tested at once, 8 to a block, is a
// few dozen vector operations (docs/performance.md, "Triangles in blocks", has the figures).
//
// Only the AVX2 width is built, with FMA, which every AVX2 CPU has: blocks of 16 with AVX-512
// rendered the Cornell box no faster. Without AVX2 and FMA there are no blocks.
//
// The test is Moeller and Trumbore's in the form Embree's own triangle leaves use (its
// Triangle4 precomputes the same edges and normal): not watertight, as Embree's default is not.
// A hit counts for t in (0, tMax); of two triangles hit at exactly the same t the lower index
// wins.
#pragma once

#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "geometry/ray.h"
#include "geometry/shapes.h"

namespace candela {

// Scenes of at most this many triangles (and no alpha masks) test them in blocks: beyond it,
// Embree's BVH gains more than its walk costs (docs/performance.md).
constexpr uint32_t kTriangleBlocksUpTo = 64;

// Blocks of `width` triangles, padded with triangles no ray hits; a block is twelve arrays of
// `width` floats, one after the other: per triangle its first vertex p0, the edges a = p0 - p1
// and b = p2 - p0, and n = a x b (p0 x, y, z; a x, y, z; b x, y, z; n x, y, z).
struct TriangleBlocksView {
  const float* data = nullptr;
  uint32_t blockCount = 0;
  uint32_t width = 8;  // triangles per block
};

// The widest block this CPU tests: 8 with AVX2 and FMA, else 0 (no blocks).
uint32_t widestTriangleBlock();

class TriangleBlocks {
 public:
  // Blocks of `count` triangles (the caller keeps to kTriangleBlocksUpTo); none where the CPU
  // has no blocks (widestTriangleBlock is 0).
  void assign(const Vec3* positions, const Triangle* triangles, uint32_t count);
  TriangleBlocksView view() const;
  size_t bytes() const { return data_.size() * sizeof(float); }

 private:
  std::vector<float> data_;  // blockCount_ blocks of twelve arrays of width_ floats
  uint32_t blockCount_ = 0;
  uint32_t width_ = 8;
};

// The two tests, compiled for AVX2 and FMA (triangle_blocks_w8.cpp); closestTriangle and
// anyTriangle call them.
bool closestTriangleW8(const TriangleBlocksView&, const Ray&, float tMax, float* t,
                       uint32_t* triangle, float* b1, float* b2);
bool anyTriangleW8(const TriangleBlocksView&, const Ray&, uint32_t skipTriangle);

// closestTriangle: the nearest triangle hit for t in (0, tMax); sets *t, *triangle (its index
// among the scene's triangles) and its barycentrics *b1, *b2 (of p1 and p2) and returns true.
// anyTriangle: whether a triangle other than `skipTriangle` is hit for t in (0, ray.tMax).
#if defined(__x86_64__)
inline bool closestTriangle(const TriangleBlocksView& blocks, const Ray& ray, float tMax, float* t,
                            uint32_t* triangle, float* b1, float* b2) {
  return closestTriangleW8(blocks, ray, tMax, t, triangle, b1, b2);
}
inline bool anyTriangle(const TriangleBlocksView& blocks, const Ray& ray, uint32_t skipTriangle) {
  return anyTriangleW8(blocks, ray, skipTriangle);
}
#else  // no blocks (widestTriangleBlock is 0), so never called
inline bool closestTriangle(const TriangleBlocksView&, const Ray&, float, float*, uint32_t*, float*,
                            float*) {
  return false;
}
inline bool anyTriangle(const TriangleBlocksView&, const Ray&, uint32_t) { return false; }
#endif

}  // namespace candela
