// The light tree: how next-event estimation picks one light among many by its importance at the
// shading point (Conty Estevez and Kulla 2018, as pbrt-v4's BVHLightSampler), not by power alone.
//
// Each node holds up to eight clusters of lights, each with a bounding sphere, its total power
// and the cone that holds its emitting normals (every candela emitter, a surface or a point,
// emits up to 90 degrees past its normals: theta_e = pi/2). A pick walks from the root, choosing
// among a node's clusters in proportion to a bound on what each can send to the point: its
// power over the squared distance, times the cosine of the smallest angle at which any of its
// surfaces can face the point, times the cosine of the smallest angle between the point's
// reflecting hemisphere and any direction to the cluster. A cluster that faces away or lies below
// the horizon gets nothing, so the half of a lamp's triangles that turn their backs to a point
// are never sampled there. Eight clusters a node, in two SSE vectors on the host, keep the walk
// shallow: its cost is the dependent loads of its nodes, about one cache miss a level.
//
// The pmf of a light at a point is the product of its clusters' shares along its path (its
// trail), computed by the same arithmetic as the pick, so multiple importance sampling sees
// exactly the probability with which the light was picked. Where the bound errs to zero a
// light is left to BSDF sampling, which MIS then weighs fully: the estimate stays unbiased.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/bits.h"
#include "core/constants.h"
#include "core/device.h"
#include "core/vec3.h"

// The host evaluates a node's clusters in SSE lanes; a CUDA thread, one lane after another.
#if !CANDELA_DEVICE_CODE && (defined(__SSE2__) || defined(_M_X64))
#include <immintrin.h>
#define CANDELA_LIGHT_TREE_SSE 1
#else
#define CANDELA_LIGHT_TREE_SSE 0
#endif

namespace candela {

constexpr int kLightTreeWidth = 8;
// A child that is a light, rather than a node, carries this bit.
constexpr uint32_t kLightTreeLeaf = 0x80000000u;

struct alignas(64) LightTreeNode {
  float centerX[kLightTreeWidth], centerY[kLightTreeWidth], centerZ[kLightTreeWidth];
  float radius[kLightTreeWidth];  // of the sphere around the cluster's box
  float axisX[kLightTreeWidth], axisY[kLightTreeWidth], axisZ[kLightTreeWidth];
  // The cone around the axis that holds every emitting normal.
  float cosThetaO[kLightTreeWidth], sinThetaO[kLightTreeWidth];
  float power[kLightTreeWidth];     // 0: an empty slot, never picked
  uint32_t child[kLightTreeWidth];  // a node index, or a light index | kLightTreeLeaf
  // 1 when the clusters share one box and one cone (the two triangles of an axis-aligned
  // quad): their importance is then in proportion to their power everywhere, which the pick
  // takes for it without evaluating it.
  uint32_t byPower;
};

// A trail holds 3 bits a level (the slot taken): the tree is at most this deep.
constexpr uint32_t kLightTreeTrailBits = 3;
constexpr uint32_t kMaxLightTreeDepth = 21;

// Lane k of lightClusterImportance: the bound on what cluster k of `node` can send to point p,
// whose reflecting hemisphere is around unit normal n (zero where the surface also transmits).
//
// The angles' cosines and sines all share the divisor d = |p - centre|, so they are carried as
// d times their value: comparisons then need no division, and the square roots and the two
// divisions do not wait on one another.
CANDELA_HDI_ALWAYS float lightClusterImportanceLane(const LightTreeNode& node, int k, const Vec3& p,
                                                    const Vec3& n) {
  const float vx = p.x - node.centerX[k], vy = p.y - node.centerY[k], vz = p.z - node.centerZ[k];
  const float d2 = maxf(vx * vx + vy * vy + vz * vz, 1e-30f);
  const float r = node.radius[k], r2 = r * r;
  const float cosO = node.cosThetaO[k], sinO = node.sinThetaO[k];
  const float invD2 = 1.0f / d2, invReach = 1.0f / maxf(d2, r2);
  const float d = sqrtf(d2);
  // theta_w, from the cone's axis to the direction from the cluster to p: d cos, d sin.
  const float cosW = node.axisX[k] * vx + node.axisY[k] * vy + node.axisZ[k] * vz;
  const float sinW = sqrtf(maxf(0.0f, d2 - cosW * cosW));
  // theta_b, the half-angle of the bounding sphere seen from p (every direction inside it).
  const bool inside = d2 <= r2;
  const float cosB = sqrtf(maxf(0.0f, d2 - r2));
  // theta_x = max(0, theta_w - theta_o): the smallest angle from an emitting normal to p.
  const bool inCone = cosW > cosO * d;
  const float cosX = inCone ? d : cosW * cosO + sinW * sinO;
  const float sinX = inCone ? 0.0f : sinW * cosO - cosW * sinO;
  // d^2 cos max(0, theta_x - theta_b): some surface faces p while it is positive.
  const float cosP = inside || cosX > cosB ? d2 : cosX * cosB + sinX * r;
  const float facing = cosP > 0.0f ? cosP * invD2 : 0.0f;
  // d^2 cos max(0, theta_i - theta_b), theta_i from n to the direction to the cluster.
  const float cosI = -(n.x * vx + n.y * vy + n.z * vz);
  const float sinI = sqrtf(maxf(0.0f, d2 - cosI * cosI));
  const float cosPI = inside || cosI > cosB ? d2 : cosI * cosB + sinI * r;
  const bool hemisphere = !isBlack(n);
  const float horizon = hemisphere ? maxf(cosPI * invD2, 0.0f) : 1.0f;
  return (node.power[k] * invReach) * (facing * horizon);
}

#if CANDELA_LIGHT_TREE_SSE
// Lanes [first, first + 4) of lightClusterImportanceLane in SSE, operation for operation the
// same arithmetic, so that both give the same bits.
CANDELA_HDI_ALWAYS __m128 lightClusterImportanceSse(const LightTreeNode& node, int first,
                                                    const Vec3& p, const Vec3& n) {
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
  const auto select = [](__m128 mask, __m128 a, __m128 b) {
    return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
  };
  const auto mul = [](__m128 a, __m128 b) { return _mm_mul_ps(a, b); };
  const auto add = [](__m128 a, __m128 b) { return _mm_add_ps(a, b); };
  const auto sub = [](__m128 a, __m128 b) { return _mm_sub_ps(a, b); };
  const auto dot = [&](__m128 ax, __m128 ay, __m128 az, __m128 bx, __m128 by, __m128 bz) {
    return add(add(mul(ax, bx), mul(ay, by)), mul(az, bz));
  };
  const auto rootOfDifference = [&](__m128 a, __m128 b) {
    return _mm_sqrt_ps(_mm_max_ps(zero, sub(a, b)));
  };
  const auto load = [first](const float* lanes) { return _mm_load_ps(lanes + first); };
  const __m128 vx = sub(_mm_set1_ps(p.x), load(node.centerX));
  const __m128 vy = sub(_mm_set1_ps(p.y), load(node.centerY));
  const __m128 vz = sub(_mm_set1_ps(p.z), load(node.centerZ));
  const __m128 d2 = _mm_max_ps(dot(vx, vy, vz, vx, vy, vz), _mm_set1_ps(1e-30f));
  const __m128 r = load(node.radius), r2 = mul(r, r);
  const __m128 cosO = load(node.cosThetaO), sinO = load(node.sinThetaO);
  const __m128 invD2 = _mm_div_ps(one, d2), invReach = _mm_div_ps(one, _mm_max_ps(d2, r2));
  const __m128 d = _mm_sqrt_ps(d2);
  const __m128 cosW = dot(load(node.axisX), load(node.axisY), load(node.axisZ), vx, vy, vz);
  const __m128 sinW = rootOfDifference(d2, mul(cosW, cosW));
  const __m128 inside = _mm_cmple_ps(d2, r2);
  const __m128 cosB = rootOfDifference(d2, r2);
  const __m128 inCone = _mm_cmpgt_ps(cosW, mul(cosO, d));
  const __m128 cosX = select(inCone, d, add(mul(cosW, cosO), mul(sinW, sinO)));
  const __m128 sinX = select(inCone, zero, sub(mul(sinW, cosO), mul(cosW, sinO)));
  const __m128 cosP =
      select(_mm_or_ps(inside, _mm_cmpgt_ps(cosX, cosB)), d2, add(mul(cosX, cosB), mul(sinX, r)));
  const __m128 facing = select(_mm_cmpgt_ps(cosP, zero), mul(cosP, invD2), zero);
  const __m128 cosI = _mm_xor_ps(
      _mm_set1_ps(-0.0f), dot(_mm_set1_ps(n.x), _mm_set1_ps(n.y), _mm_set1_ps(n.z), vx, vy, vz));
  const __m128 sinI = rootOfDifference(d2, mul(cosI, cosI));
  const __m128 cosPI =
      select(_mm_or_ps(inside, _mm_cmpgt_ps(cosI, cosB)), d2, add(mul(cosI, cosB), mul(sinI, r)));
  const bool hemisphere = !isBlack(n);
  const __m128 horizon = hemisphere ? _mm_max_ps(mul(cosPI, invD2), zero) : one;
  return mul(mul(load(node.power), invReach), mul(facing, horizon));
}

// Running sums of four lanes, in the order of a log-step prefix sum.
CANDELA_HDI_ALWAYS __m128 prefixSums(__m128 i) {
  const __m128 q = _mm_add_ps(i, _mm_castsi128_ps(_mm_slli_si128(_mm_castps_si128(i), 4)));
  return _mm_add_ps(q, _mm_castsi128_ps(_mm_slli_si128(_mm_castps_si128(q), 8)));
}
#endif

// What a pick needs of a node at a point: each cluster's importance and where its share of
// [0, total) ends (ends[kLightTreeWidth - 1] is the total), summed in one fixed order, that of
// SSE's log-step prefix sums, on every backend.
struct ClusterShares {
  float importance[kLightTreeWidth];
  float ends[kLightTreeWidth];
  int positive;  // bit k: cluster k has importance
};

// Bit k set where ends[k] > target.
CANDELA_HDI_ALWAYS int sharesEndingBeyond(const ClusterShares& s, float target) {
#if CANDELA_LIGHT_TREE_SSE
  const __m128 t = _mm_set1_ps(target);
  return _mm_movemask_ps(_mm_cmplt_ps(t, _mm_loadu_ps(s.ends))) |
         _mm_movemask_ps(_mm_cmplt_ps(t, _mm_loadu_ps(s.ends + 4))) << 4;
#else
  int beyond = 0;
  for (int k = 0; k < kLightTreeWidth; ++k) beyond |= (target < s.ends[k] ? 1 : 0) << k;
  return beyond;
#endif
}

// Fills s->ends from s->importance, in the order of clusterShares's SSE sums.
CANDELA_HDI_ALWAYS void prefixEnds(ClusterShares* s) {
  for (int h = 0; h < kLightTreeWidth; h += 4) {
    const float* i = s->importance + h;
    float* e = s->ends + h;
    e[0] = i[0];
    e[1] = i[1] + i[0];
    e[2] = (i[2] + i[1]) + i[0];
    e[3] = (i[3] + i[2]) + (i[1] + i[0]);
    if (h > 0)
      for (int k = 0; k < 4; ++k) e[k] += s->ends[h - 1];
  }
}

CANDELA_HDI_ALWAYS void clusterShares(const LightTreeNode& node, const Vec3& p, const Vec3& n,
                                      ClusterShares* s) {
#if CANDELA_LIGHT_TREE_SSE
  // Clusters fill a node from its first lane: a node of four or fewer (a small scene's only
  // node) leaves the second vector empty.
  __m128 low, high;
  if (node.byPower) {
    low = _mm_loadu_ps(node.power);
    high = _mm_loadu_ps(node.power + 4);
  } else {
    low = lightClusterImportanceSse(node, 0, p, n);
    high = node.power[4] > 0.0f ? lightClusterImportanceSse(node, 4, p, n) : _mm_setzero_ps();
  }
  const __m128 lowEnds = prefixSums(low);
  const __m128 highEnds =
      _mm_add_ps(prefixSums(high), _mm_shuffle_ps(lowEnds, lowEnds, _MM_SHUFFLE(3, 3, 3, 3)));
  _mm_storeu_ps(s->importance, low);
  _mm_storeu_ps(s->importance + 4, high);
  _mm_storeu_ps(s->ends, lowEnds);
  _mm_storeu_ps(s->ends + 4, highEnds);
  s->positive = _mm_movemask_ps(_mm_cmpgt_ps(low, _mm_setzero_ps())) |
                _mm_movemask_ps(_mm_cmpgt_ps(high, _mm_setzero_ps())) << 4;
#else
  s->positive = 0;
  for (int k = 0; k < kLightTreeWidth; ++k) {
    s->importance[k] = node.byPower ? node.power[k] : lightClusterImportanceLane(node, k, p, n);
    s->positive |= (s->importance[k] > 0.0f ? 1 : 0) << k;
  }
  prefixEnds(s);
#endif
}

// Picks a light of the tree `nodes` (at least one node) for the point p with hemisphere normal n
// (lightClusterImportanceLane) from uniform u in [0, 1): its index and, in *pmf, the probability
// of the pick, in *remapped u's place within the light's share. -1 when no light can reach p.
CANDELA_HDI int pickTreeLight(const LightTreeNode* nodes, const Vec3& p, const Vec3& n, float u,
                              float* pmf, float* remapped) {
  uint32_t node = 0;
  float probability = 1.0f;
  for (;;) {
    ClusterShares s;
    clusterShares(nodes[node], p, n, &s);
    const float total = s.ends[kLightTreeWidth - 1];
    if (!(total > 0.0f)) return -1;
    // The first cluster with importance whose share ends beyond u total (else, should rounding
    // carry u total past them all, the last with importance).
    const float target = u * total;
    const int beyond = sharesEndingBeyond(s, target) & s.positive;
    const int k = beyond ? lowestSetBit(uint32_t(beyond)) : highestSetBit(uint32_t(s.positive));
    probability *= s.importance[k] / total;
    // u's place within the share, for the next level (or the caller). The share's start found
    // from its end, not by a branch on k, a coin toss where the tree has a choice (its rounding,
    // an ulp of the end, moves u's place by as little).
    const float start = s.ends[k] - s.importance[k];
    u = minf(maxf((target - start) / s.importance[k], 0.0f), kOneMinusEpsilon);
    const uint32_t child = nodes[node].child[k];
    if (child & kLightTreeLeaf) {
      *pmf = probability;
      *remapped = u;
      return int(child & ~kLightTreeLeaf);
    }
    node = child;
  }
}

// The probability with which pickTreeLight picks the light whose trail is `trail`.
CANDELA_HDI float treeLightPmf(const LightTreeNode* nodes, uint64_t trail, const Vec3& p,
                               const Vec3& n) {
  uint32_t node = 0;
  float probability = 1.0f;
  for (;;) {
    ClusterShares s;
    clusterShares(nodes[node], p, n, &s);
    const int k = int(trail & ((1u << kLightTreeTrailBits) - 1));
    trail >>= kLightTreeTrailBits;
    if (!(s.importance[k] > 0.0f)) return 0.0f;
    probability *= s.importance[k] / s.ends[kLightTreeWidth - 1];
    const uint32_t child = nodes[node].child[k];
    if (child & kLightTreeLeaf) return probability;
    node = child;
  }
}

}  // namespace candela
