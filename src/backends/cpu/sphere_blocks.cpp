#include "backends/cpu/sphere_blocks.h"

#include "geometry/motion.h"

#if !defined(__x86_64__)
#include "geometry/sphere_intersect.h"
#endif

namespace candela {

void SphereBlocks::assign(const Sphere* spheres, uint32_t count, uint32_t maxWidth,
                          const uint32_t* motions) {
  // The narrowest block that holds them all, within maxWidth: a wider block's lanes beyond the
  // spheres would only be tested in vain.
  width_ = 4;
  while (width_ < maxWidth && width_ < count) width_ *= 2;
  blockCount_ = (count + width_ - 1) / width_;
  const size_t lanes = size_t(blockCount_) * width_;
  data_.assign(5 * lanes, 0.0f);
  float* centerX = data_.data();
  float* centerY = centerX + lanes;
  float* centerZ = centerY + lanes;
  float* radius = centerZ + lanes;
  float* radiusSquared = radius + lanes;
  for (size_t i = 0; i < lanes; ++i) {
    // A padding lane has radius -1: every ray passes farther than that from its centre. Its
    // squared radius, far below zero, makes blockHits's first look call it wide of every ray.
    const bool blank = i >= count || (motions && motions[i] != kStill);
    const Sphere s = blank ? Sphere{Vec3(0, 0, 0), -1.0f} : spheres[i];
    centerX[i] = s.center.x;
    centerY[i] = s.center.y;
    centerZ[i] = s.center.z;
    radius[i] = s.radius;
    radiusSquared[i] = blank ? -1e30f : s.radius * s.radius;
  }
}

SphereBlocksView SphereBlocks::view() const {
  const size_t lanes = size_t(blockCount_) * width_;
  SphereBlocksView v;
  v.centerX = data_.data();
  v.centerY = v.centerX + lanes;
  v.centerZ = v.centerY + lanes;
  v.radius = v.centerZ + lanes;
  v.radiusSquared = v.radius + lanes;
  v.blockCount = blockCount_;
  v.width = width_;
  return v;
}

#if defined(__x86_64__)

uint32_t widestSphereBlock() {
  static const uint32_t widest = __builtin_cpu_supports("avx2") ? 8 : 4;
  return widest;
}

bool closestSphere(const SphereBlocksView& blocks, const Ray& ray, float tMax, float* t,
                   uint32_t* prim) {
  return blocks.width == 8 ? closestSphereW8(blocks, ray, tMax, t, prim)
                           : closestSphereW4(blocks, ray, tMax, t, prim);
}

bool anySphere(const SphereBlocksView& blocks, const Ray& ray, uint32_t skipPrim) {
  return blocks.width == 8 ? anySphereW8(blocks, ray, skipPrim)
                           : anySphereW4(blocks, ray, skipPrim);
}

#else  // not x86-64: the same tests one sphere at a time

uint32_t widestSphereBlock() { return 4; }

namespace {
Sphere sphereAt(const SphereBlocksView& b, uint32_t i) {
  Sphere s;
  s.center = Vec3(b.centerX[i], b.centerY[i], b.centerZ[i]);
  s.radius = b.radius[i];
  return s;
}
}  // namespace

bool closestSphere(const SphereBlocksView& blocks, const Ray& ray, float tMax, float* t,
                   uint32_t* prim) {
  bool found = false;
  for (uint32_t i = 0; i < blocks.blockCount * blocks.width; ++i) {
    float ti;
    if (!intersectSphere(sphereAt(blocks, i), ray, tMax, &ti)) continue;
    tMax = *t = ti;
    *prim = i;
    found = true;
  }
  return found;
}

bool anySphere(const SphereBlocksView& blocks, const Ray& ray, uint32_t skipPrim) {
  float t;
  for (uint32_t i = 0; i < blocks.blockCount * blocks.width; ++i)
    if (i != skipPrim && intersectSphere(sphereAt(blocks, i), ray, ray.tMax, &t)) return true;
  return false;
}

#endif

}  // namespace candela
