#include "backends/cpu/sphere_blocks.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#else
#include "geometry/sphere_intersect.h"
#endif

namespace candela {

void SphereBlocks::assign(const Sphere* spheres, uint32_t count) {
  blockCount_ = (count + 3) / 4;
  const size_t lanes = size_t(blockCount_) * 4;
  data_.assign(5 * lanes, 0.0f);
  float* centerX = data_.data();
  float* centerY = centerX + lanes;
  float* centerZ = centerY + lanes;
  float* radius = centerZ + lanes;
  float* radiusSquared = radius + lanes;
  for (size_t i = 0; i < lanes; ++i) {
    // A padding lane has radius -1: every ray passes farther than that from its centre. Its
    // squared radius, far below zero, makes blockHits's first look call it wide of every ray.
    const Sphere s = i < count ? spheres[i] : Sphere{Vec3(0, 0, 0), -1.0f};
    centerX[i] = s.center.x;
    centerY[i] = s.center.y;
    centerZ[i] = s.center.z;
    radius[i] = s.radius;
    radiusSquared[i] = i < count ? s.radius * s.radius : -1e30f;
  }
}

SphereBlocksView SphereBlocks::view() const {
  const size_t lanes = size_t(blockCount_) * 4;
  SphereBlocksView v;
  v.centerX = data_.data();
  v.centerY = v.centerX + lanes;
  v.centerZ = v.centerY + lanes;
  v.radius = v.centerZ + lanes;
  v.radiusSquared = v.radius + lanes;
  v.blockCount = blockCount_;
  return v;
}

#if defined(__SSE2__)

namespace {

struct RayLanes {
  __m128 ox, oy, oz, dx, dy, dz, a;
  explicit RayLanes(const Ray& r)
      : ox(_mm_set1_ps(r.origin.x)),
        oy(_mm_set1_ps(r.origin.y)),
        oz(_mm_set1_ps(r.origin.z)),
        dx(_mm_set1_ps(r.direction.x)),
        dy(_mm_set1_ps(r.direction.y)),
        dz(_mm_set1_ps(r.direction.z)),
        a(_mm_set1_ps(lengthSquared(r.direction))) {}
};

inline __m128 select(__m128 mask, __m128 ifSet, __m128 ifClear) {
  return _mm_or_ps(_mm_and_ps(mask, ifSet), _mm_andnot_ps(mask, ifClear));
}

// intersectSphere on the four spheres of block `block`, lane by lane: returns the hit distances,
// and in *hit all ones in the lanes that hit for t in (0, tMax). Returns false, *hit untouched,
// when a first cheap look, before any division or square root, shows that no lane can hit.
inline bool blockHits(const SphereBlocksView& b, uint32_t block, const RayLanes& r, float tMax,
                      __m128* distances, __m128* hit) {
  const size_t o = size_t(block) * 4;
  const __m128 zero = _mm_setzero_ps();
  const __m128 signBit = _mm_set1_ps(-0.0f);
  const __m128 tMaxLanes = _mm_set1_ps(tMax);
  const __m128 ocx = _mm_sub_ps(r.ox, _mm_load_ps(b.centerX + o));
  const __m128 ocy = _mm_sub_ps(r.oy, _mm_load_ps(b.centerY + o));
  const __m128 ocz = _mm_sub_ps(r.oz, _mm_load_ps(b.centerZ + o));
  const __m128 halfB =
      _mm_add_ps(_mm_add_ps(_mm_mul_ps(ocx, r.dx), _mm_mul_ps(ocy, r.dy)), _mm_mul_ps(ocz, r.dz));
  const __m128 ocSquared =
      _mm_add_ps(_mm_add_ps(_mm_mul_ps(ocx, ocx), _mm_mul_ps(ocy, ocy)), _mm_mul_ps(ocz, ocz));
  const __m128 radiusSquared = _mm_load_ps(b.radiusSquared + o);
  const __m128 c = _mm_sub_ps(ocSquared, radiusSquared);
  // From outside, moving away or with the near root beyond tMax: a miss (intersectSphere's test).
  const __m128 beyond =
      _mm_and_ps(_mm_cmpgt_ps(c, zero),
                 _mm_cmpge_ps(c, _mm_mul_ps(tMaxLanes, _mm_mul_ps(_mm_set1_ps(-2.0f), halfB))));
  // Passing clearly wide: a |perp|^2 = a |oc|^2 - halfB^2 exceeds a r^2 by more than the rounding
  // of either side (both err by a few ulp of a (|oc|^2 + r^2)), so the exact test below misses.
  const __m128 aPerpSquared = _mm_sub_ps(_mm_mul_ps(r.a, ocSquared), _mm_mul_ps(halfB, halfB));
  const __m128 margin = _mm_mul_ps(_mm_mul_ps(_mm_set1_ps(1e-6f), r.a),
                                   _mm_add_ps(ocSquared, radiusSquared));
  const __m128 wide =
      _mm_cmpgt_ps(_mm_sub_ps(aPerpSquared, _mm_mul_ps(r.a, radiusSquared)), margin);
  if (_mm_movemask_ps(_mm_or_ps(beyond, wide)) == 0xf) return false;

  const __m128 radius = _mm_load_ps(b.radius + o);
  const __m128 k = _mm_div_ps(halfB, r.a);
  const __m128 px = _mm_sub_ps(ocx, _mm_mul_ps(k, r.dx));
  const __m128 py = _mm_sub_ps(ocy, _mm_mul_ps(k, r.dy));
  const __m128 pz = _mm_sub_ps(ocz, _mm_mul_ps(k, r.dz));
  const __m128 perpLength = _mm_sqrt_ps(
      _mm_add_ps(_mm_add_ps(_mm_mul_ps(px, px), _mm_mul_ps(py, py)), _mm_mul_ps(pz, pz)));
  const __m128 passesBy = _mm_cmpgt_ps(perpLength, radius);
  const __m128 discriminant = _mm_mul_ps(_mm_mul_ps(r.a, _mm_sub_ps(radius, perpLength)),
                                         _mm_add_ps(radius, perpLength));
  const __m128 signedRoot = _mm_or_ps(_mm_andnot_ps(signBit, _mm_sqrt_ps(discriminant)),
                                      _mm_and_ps(signBit, halfB));
  const __m128 q = _mm_xor_ps(_mm_add_ps(halfB, signedRoot), signBit);
  const __m128 t0 = _mm_div_ps(q, r.a);
  const __m128 t1 = _mm_div_ps(c, q);
  const __m128 swapped = _mm_cmpgt_ps(t0, t1);
  const __m128 nearT = select(swapped, t1, t0);
  const __m128 farT = select(swapped, t0, t1);
  const __m128 nearOk = _mm_and_ps(_mm_cmpgt_ps(nearT, zero), _mm_cmplt_ps(nearT, tMaxLanes));
  const __m128 farOk = _mm_and_ps(_mm_cmpgt_ps(farT, zero), _mm_cmplt_ps(farT, tMaxLanes));
  *hit = _mm_andnot_ps(_mm_or_ps(beyond, passesBy), _mm_or_ps(nearOk, farOk));
  *distances = select(nearOk, nearT, farT);
  return true;
}

}  // namespace

bool closestSphere(const SphereBlocksView& blocks, const Ray& ray, float tMax, float* t,
                   uint32_t* prim) {
  // Every block is tested against the same tMax, so blocks do not wait on each other's results;
  // each lane keeps its nearest hit (the earliest block's on a tie), and the lanes are compared
  // at the end. A smaller tMax would only have turned hits beyond the nearest into misses.
  const RayLanes lanes(ray);
  __m128 nearest = _mm_set1_ps(tMax);
  __m128i nearestBlock = _mm_setzero_si128();
  for (uint32_t block = 0; block < blocks.blockCount; ++block) {
    __m128 distances, hit;
    if (!blockHits(blocks, block, lanes, tMax, &distances, &hit)) continue;
    const __m128 nearer = _mm_and_ps(_mm_cmplt_ps(distances, nearest), hit);
    nearest = select(nearer, distances, nearest);
    const __m128i nearerBits = _mm_castps_si128(nearer);
    nearestBlock = _mm_or_si128(_mm_and_si128(nearerBits, _mm_set1_epi32(int(block))),
                                _mm_andnot_si128(nearerBits, nearestBlock));
  }
  alignas(16) float laneT[4];
  alignas(16) uint32_t laneBlock[4];
  _mm_store_ps(laneT, nearest);
  _mm_store_si128(reinterpret_cast<__m128i*>(laneBlock), nearestBlock);
  bool found = false;
  for (uint32_t lane = 0; lane < 4; ++lane) {
    const uint32_t index = laneBlock[lane] * 4 + lane;
    const bool tieWithLowerIndex = found && laneT[lane] == tMax && index < *prim;
    if (!(laneT[lane] < tMax) && !tieWithLowerIndex) continue;
    tMax = laneT[lane];
    *t = tMax;
    *prim = index;
    found = true;
  }
  return found;
}

bool anySphere(const SphereBlocksView& blocks, const Ray& ray, uint32_t skipPrim) {
  const RayLanes lanes(ray);
  for (uint32_t block = 0; block < blocks.blockCount; ++block) {
    __m128 distances, hit;
    if (!blockHits(blocks, block, lanes, ray.tMax, &distances, &hit)) continue;
    int hitLanes = _mm_movemask_ps(hit);
    if (skipPrim - block * 4 < 4) hitLanes &= ~(1 << (skipPrim - block * 4));
    if (hitLanes != 0) return true;
  }
  return false;
}

#else  // no SSE: the same tests one sphere at a time

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
  for (uint32_t i = 0; i < blocks.blockCount * 4; ++i) {
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
  for (uint32_t i = 0; i < blocks.blockCount * 4; ++i)
    if (i != skipPrim && intersectSphere(sphereAt(blocks, i), ray, ray.tMax, &t)) return true;
  return false;
}

#endif

}  // namespace candela
