#include "backends/cpu/triangle_blocks.h"

namespace candela {

void TriangleBlocks::assign(const Vec3* positions, const Triangle* triangles, uint32_t count) {
  const uint32_t width = widestTriangleBlock();
  blockCount_ = 0;
  data_.clear();
  if (width == 0 || count == 0) return;
  width_ = width;
  blockCount_ = (count + width_ - 1) / width_;
  // A padding lane is all zeros: its det is 0, which no hit has.
  data_.assign(size_t(blockCount_) * 12 * width_, 0.0f);
  for (size_t i = 0; i < count; ++i) {
    float* block = data_.data() + (i / width_) * 12 * width_;
    const size_t lane = i % width_;
    const Triangle& tri = triangles[i];
    const Vec3 p0 = positions[tri.v[0]], p1 = positions[tri.v[1]], p2 = positions[tri.v[2]];
    const Vec3 a = p0 - p1, b = p2 - p0;
    const Vec3 values[4] = {p0, a, b, cross(a, b)};
    for (int k = 0; k < 4; ++k) {
      block[(3 * k + 0) * width_ + lane] = values[k].x;
      block[(3 * k + 1) * width_ + lane] = values[k].y;
      block[(3 * k + 2) * width_ + lane] = values[k].z;
    }
  }
}

TriangleBlocksView TriangleBlocks::view() const {
  TriangleBlocksView v;
  if (blockCount_ == 0) return v;
  v.data = data_.data();
  v.blockCount = blockCount_;
  v.width = width_;
  return v;
}

#if defined(__x86_64__)

uint32_t widestTriangleBlock() {
  static const uint32_t widest =
      __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") ? 8 : 0;
  return widest;
}

#else  // not x86-64: no blocks

uint32_t widestTriangleBlock() { return 0; }

#endif

}  // namespace candela
