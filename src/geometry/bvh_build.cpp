// Binned SAH BVH build (see bvh_build.h for the layout it produces).
//
// Structure of the build:
// 1. One parallel pass computes every primitive's bounds into a BuildPrim array, plus the root's
//    bounds and centroid bounds.
// 2. Nodes are split recursively. Each split bins the centroids along all three axes (four lanes
//    at once), picks the cheapest SAH plane, or the split of large from small primitives when
//    that is much cheaper, and partitions the BuildPrim range in place; the bins give the
//    children's bounds, and a pass over each child after the partition its centroid bounds.
// 3. Large subtrees (the "top" of the tree) are split in parallel with oneTBB; below
//    kParallelThreshold primitives a subtree is built serially, depth-first. Every subtree is
//    written straight into its own slots of one node array, sized by a bound on its node count
//    (buildTop), so no node is ever copied; the array is then collapsed into 4-wide nodes.
// Every decision depends only on the data, never on the thread schedule: the tree is the same for
// any thread count.
#include "geometry/bvh_build.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <new>
#include <utility>

#include "core/float4.h"
#include "core/float_error.h"
#include "geometry/aabb.h"
#include "geometry/primitive_bounds.h"

namespace candela {
namespace {

// Centroid bins per axis; small nodes use one bin per primitive, as more cannot help them.
constexpr int kMaxBins = 16;
// SAH cost of visiting an interior node, relative to one primitive intersection: above pbrt-v4's
// 1/2, since it renders as fast with fewer nodes and bytes (docs/performance.md).
constexpr float kTraversalCost = 1.25f;
// Below this depth splits follow the SAH; from it on they are object medians, which halve the
// primitive count at each level and so bound the depth by kSahDepthLimit + 30 <= kBvhMaxDepth
// for any 32-bit primitive count.
constexpr uint32_t kSahDepthLimit = 32;
// Nodes with more primitives than this bin along the widest centroid axis only; smaller ones try
// all three. Binning is most of the build's time, and on large nodes the widest axis is nearly
// always the best one (docs/performance.md).
constexpr uint32_t kAllAxesBelow = 1024;
// Subtrees with at least this many primitives are split in parallel; smaller ones are built
// serially into one chunk. Small enough that a 4k-triangle scene (the cat) keeps two cores busy
// and chunks balance; a task costs microseconds, a 1k-primitive chunk about a tenth of a
// millisecond.
constexpr uint32_t kParallelThreshold = 1u << 10;

// A box as two Float4s; lane 3 is unused (it may carry anything, see BuildPrim).
struct Box4 {
  Float4 lo{kInfinity}, hi{-kInfinity};

  void grow(Float4 p) {
    lo = min(lo, p);
    hi = max(hi, p);
  }
  void grow(Float4 pLo, Float4 pHi) {
    lo = min(lo, pLo);
    hi = max(hi, pHi);
  }
  void grow(const Box4& b) { grow(b.lo, b.hi); }
  float extent(int axis) const { return hi[axis] - lo[axis]; }
  // Half the surface area (the SAH only compares areas); 0 for an empty box.
  float halfArea() const {
    const Float4 d = max(hi - lo, Float4(0.0f));
    const float x = d.x(), y = d.y(), z = d.z();
    return x * y + y * z + z * x;
  }
  int widestAxis() const {
    const Float4 d = hi - lo;
    const float x = d.x(), y = d.y(), z = d.z();
    return x >= y && x >= z ? 0 : (y >= z ? 1 : 2);
  }
  float widestExtent() const { return extent(widestAxis()); }
  Bounds3 bounds() const {
    return Bounds3(Vec3(lo.x(), lo.y(), lo.z()), Vec3(hi.x(), hi.y(), hi.z()));
  }
};

// A primitive while building: its bounds, laid out as two 16-byte rows so that the binning loop
// reads each with one load. The index rides in lane 3 of the lower row, where box arithmetic
// ignores it.
struct alignas(16) BuildPrim {
  float lo[3];
  uint32_t index;
  float hi[3];
  float pad;

  BuildPrim() = default;
  BuildPrim(const Bounds3& b, uint32_t index_)
      : lo{b.lo.x, b.lo.y, b.lo.z}, index(index_), hi{b.hi.x, b.hi.y, b.hi.z}, pad(0.0f) {}
  Float4 lower() const { return Float4::load(lo); }
  Float4 upper() const { return Float4::load(hi); }
  // Twice the centroid: binning only needs centroids up to a common scale.
  Float4 centroid2() const { return lower() + upper(); }
};
static_assert(sizeof(BuildPrim) == 32, "BuildPrim is two 16-byte rows");

struct BuildStats {
  uint32_t leafCount = 0;
  uint32_t maxDepth = 0;

  void addLeaf(uint32_t depth) {
    ++leafCount;
    maxDepth = std::max(maxDepth, depth);
  }
  void merge(const BuildStats& o) {
    leafCount += o.leafCount;
    maxDepth = std::max(maxDepth, o.maxDepth);
  }
};

// A node range: primitives [begin, end) of the BuildPrim array, their bounds and the bounds of
// their (doubled) centroids.
struct NodeRange {
  uint32_t begin, end;
  Box4 bounds, centroids;

  uint32_t count() const { return end - begin; }
};

// Maps doubled centroids to `bins` bins along all three axes at once. Built from the node's
// centroid bounds, so the minimum falls in bin 0 and the maximum in the last bin; a flat axis
// puts everything in bin 0, and so does a NaN centroid. Binning and partitioning both call
// binsOf, so a primitive always lands on the side its bin was counted on.
class BinMapping {
 public:
  BinMapping(const Box4& centroids, int bins) : last_(float(bins - 1)) {
    for (int axis = 0; axis < 3; ++axis) {
      origin_[axis] = centroids.lo[axis];
      scale_[axis] = scaleFor(centroids.extent(axis), bins);
    }
    originV_ = Float4::load(origin_);
    scaleV_ = Float4::load(scale_);
  }
  // Bins per unit of centroid extent; 0 for a flat axis or one too thin to scale, which puts
  // every centroid in bin 0.
  static float scaleFor(float extent, int bins) {
    const float s = static_cast<float>(bins) / extent;
    return extent > 0.0f && std::isfinite(s) ? s : 0.0f;
  }
  // The bins of a doubled centroid along x, y and z (lane 3 is meaningless).
  void binsOf(Float4 centroid2, int32_t bin[4]) const {
    // max(NaN, 0) is 0 (SSE's rule, kept by Float4), so NaN centroids land in bin 0.
    const Float4 f = min(max((centroid2 - originV_) * scaleV_, Float4(0.0f)), Float4(last_));
    truncateToInt(f, bin);
  }
  // The same as binsOf for one axis, with the same operations in the same order, so the two
  // agree to the bit.
  int binOf(int axis, float centroid2) const {
    float f = (centroid2 - origin_[axis]) * scale_[axis];
    f = f > 0.0f ? f : 0.0f;
    f = f < last_ ? f : last_;
    return static_cast<int>(f);
  }

 private:
  float origin_[4] = {}, scale_[4] = {};
  Float4 originV_, scaleV_;
  float last_;
};

// Whether a primitive is large for a node: wider than kLargeFraction of the node along some
// axis.
constexpr float kLargeFraction = 0.25f;
// The size split must beat the best plane by this factor. Greedy SAH takes any local gain, and
// on Sponza it would peel big floor and wall quads off node after node, at a cost to the whole
// tree; a room's walls gain far more than 2x (docs/performance.md).
constexpr float kSizeSplitAdvantage = 0.5f;
// Nodes with fewer primitives than this do not price the size split.
constexpr uint32_t kSizeSplitMinCount = 64;
class LargeTest {
 public:
  explicit LargeTest(const Box4& node) : limit_(Float4(kLargeFraction) * (node.hi - node.lo)) {}
  bool operator()(Float4 lo, Float4 hi) const { return anyGreaterXyz(hi - lo, limit_); }

 private:
  Float4 limit_;
};

// The size split's two sides as binning sums them: the bounds and count of a node's large
// primitives, and the bounds of the rest.
struct SizeSplitSums {
  Box4 large, small;
  uint32_t largeCount = 0;

  void add(const LargeTest& isLarge, Float4 lo, Float4 hi) {
    if (isLarge(lo, hi)) {
      large.grow(lo, hi);
      ++largeCount;
    } else {
      small.grow(lo, hi);
    }
  }
};

// The centroid bins of one node: each bin's bounds and primitive count, per axis.
class SahBins {
 public:
  // Raw storage: only the bins in use are initialised (most nodes are small).
  SahBins(int firstAxis, int lastAxis, int binCount) {
    for (int axis = firstAxis; axis <= lastAxis; ++axis) {
      for (int k = 0; k < binCount; ++k) {
        new (&storage_[axis][k].box) Box4();
        sizes_[axis][k] = 0;
      }
    }
  }
  void add(int axis, int k, Float4 lo, Float4 hi) {
    storage_[axis][k].box.grow(lo, hi);
    ++sizes_[axis][k];
  }
  const Box4& bounds(int axis, int k) const { return storage_[axis][k].box; }
  uint32_t size(int axis, int k) const { return sizes_[axis][k]; }

 private:
  union Storage {
    Storage() {}
    Box4 box;
  } storage_[3][kMaxBins];
  uint32_t sizes_[3][kMaxBins];
};

// The cheapest bin plane found so far: its SAH cost, its axis and the last bin it sends left
// (a plane after bin k sends bins [0, k] left); axis -1 while none separates the primitives.
struct PlaneSplit {
  float cost = kInfinity;
  int axis = -1, plane = -1;
};

// What sahSplit makes of a node.
enum class SahChoice { kLeaf, kPlane, kSize };

// The outcome of splitting a node: the two child ranges and the split axis.
struct Split {
  NodeRange left, right;
  int axis;
};

BinaryBvhNode makeLeaf(const Box4& bounds, uint32_t first, uint32_t count) {
  BinaryBvhNode n;
  const Bounds3 b = bounds.bounds();
  n.boundsMin = b.lo;
  n.boundsMax = b.hi;
  n.offset = first;
  n.primCount = static_cast<uint16_t>(count);
  n.axis = 0;
  n.pad = 0;
  return n;
}

BinaryBvhNode makeInterior(const Box4& bounds, int axis) {
  BinaryBvhNode n;
  const Bounds3 b = bounds.bounds();
  n.boundsMin = b.lo;
  n.boundsMax = b.hi;
  n.offset = 0;  // set once the second child's position is known
  n.primCount = 0;
  n.axis = static_cast<uint8_t>(axis);
  n.pad = 0;
  return n;
}

// Splits node ranges of one BuildPrim array, partitioning it in place. Concurrent calls are safe
// on disjoint ranges, which is all the parallel top of the build makes.
class Builder {
 public:
  explicit Builder(BuildPrim* prims) : prims_(prims) {}

  // Splits `range` into two non-empty halves, or returns false when it should be a leaf.
  bool split(const NodeRange& range, uint32_t depth, Split* out) {
    const uint32_t count = range.count();
    if (count <= 1) return false;
    if (depth >= kSahDepthLimit || range.centroids.widestExtent() <= 0.0f) {
      if (count <= kBvhMaxLeafSize) return false;
      medianSplit(range, out);
      return true;
    }
    if (sahSplit(range, out)) return true;
    // The SAH chose a leaf, or no bin plane separates the centroids (a spread too small to bin).
    if (count <= kBvhMaxLeafSize) return false;
    medianSplit(range, out);
    return true;
  }

  // Builds the subtree of `range` depth-first into nodes[next], nodes[next + 1], ..., advancing
  // `next`; offsets are indices into `nodes`.
  void buildSerial(const NodeRange& range, uint32_t depth, BinaryBvhNode* nodes, uint32_t& next,
                   BuildStats& stats) {
    const uint32_t index = next++;
    Split s;
    if (!split(range, depth, &s)) {
      new (&nodes[index]) BinaryBvhNode(makeLeaf(range.bounds, range.begin, range.count()));
      stats.addLeaf(depth);
      return;
    }
    new (&nodes[index]) BinaryBvhNode(makeInterior(range.bounds, s.axis));
    buildSerial(s.left, depth + 1, nodes, next, stats);
    nodes[index].offset = next;
    buildSerial(s.right, depth + 1, nodes, next, stats);
  }

 private:
  // Binned SAH (over all three axes for small nodes, the widest one for large nodes). Returns
  // false when the node is cheaper as a leaf (only allowed for at most kBvhMaxLeafSize
  // primitives) or when no plane separates the centroids.
  bool sahSplit(const NodeRange& range, Split* out) {
    const uint32_t count = range.count();
    if (count == 2) return pairSplit(range, out);
    const int binCount = static_cast<int>(std::min<uint32_t>(kMaxBins, count));
    const BinMapping map(range.centroids, binCount);
    const bool allAxes = count < kAllAxesBelow;
    const int widest = range.centroids.widestAxis();
    const int firstAxis = allAxes ? 0 : widest, lastAxis = allAxes ? 2 : widest;

    SahBins bins(firstAxis, lastAxis, binCount);
    // Besides the planes, one candidate that no plane can express: the primitives spanning a
    // large part of the node (a room's wall spheres, a ground quad) on one side, the rest on the
    // other. Centroid planes mix such primitives with the small ones, so every child box grows
    // to the room's size and rays visit all of them; set apart, the small ones get a tight box.
    const LargeTest isLarge(range.bounds);
    SizeSplitSums sizes;
    if (allAxes) {
      binAllAxes(range, map, bins);
      // Small nodes skip the size split: where large and small primitives alternate at random,
      // it rarely wins.
      if (count >= kSizeSplitMinCount) sumSizeSplit(range, isLarge, sizes);
    } else {
      static_assert(kAllAxesBelow >= kSizeSplitMinCount, "large nodes always price the size split");
      binAxisAndSizeSplit(range, map, widest, isLarge, bins, sizes);
    }

    const PlaneSplit plane = cheapestPlane(bins, firstAxis, lastAxis, binCount, count);
    const SahChoice choice = chooseSplit(range, plane, sizes);
    if (choice == SahChoice::kLeaf) return false;
    if (choice == SahChoice::kSize) {
      splitBySize(range, isLarge, sizes, out);
    } else {
      splitAtPlane(range, map, bins, binCount, plane, out);
    }
    return true;
  }

  // Bins every primitive of a small node along all three axes at once.
  void binAllAxes(const NodeRange& range, const BinMapping& map, SahBins& bins) const {
    int32_t bin[4];
    for (uint32_t i = range.begin; i < range.end; ++i) {
      const BuildPrim& p = prims_[i];
      const Float4 lo = p.lower(), hi = p.upper();
      map.binsOf(lo + hi, bin);
      for (int axis = 0; axis < 3; ++axis) bins.add(axis, bin[axis], lo, hi);
    }
  }

  // The size split's sums for a small node, in a pass of its own: folded into binAllAxes' loop
  // it slowed the build (docs/performance.md).
  void sumSizeSplit(const NodeRange& range, const LargeTest& isLarge, SizeSplitSums& sizes) const {
    for (uint32_t i = range.begin; i < range.end; ++i) {
      sizes.add(isLarge, prims_[i].lower(), prims_[i].upper());
    }
  }

  // Bins a large node along `axis` only, summing the size split in the same loop: a pass of its
  // own would read a large node from memory again.
  void binAxisAndSizeSplit(const NodeRange& range, const BinMapping& map, int axis,
                           const LargeTest& isLarge, SahBins& bins, SizeSplitSums& sizes) const {
    for (uint32_t i = range.begin; i < range.end; ++i) {
      const BuildPrim& p = prims_[i];
      const Float4 lo = p.lower(), hi = p.upper();
      bins.add(axis, map.binOf(axis, p.lo[axis] + p.hi[axis]), lo, hi);
      sizes.add(isLarge, lo, hi);
    }
  }

  // The cheapest plane over the binned axes, for a node of `count` primitives.
  static PlaneSplit cheapestPlane(const SahBins& bins, int firstAxis, int lastAxis, int binCount,
                                  uint32_t count) {
    PlaneSplit best;
    for (int axis = firstAxis; axis <= lastAxis; ++axis) {
      sweepAxis(bins, axis, binCount, count, best);
    }
    return best;
  }

  // Prices every plane along `axis`, keeping the cheapest in `best` (ties keep the earlier
  // plane): a sweep from the right collects suffix costs, one from the left finds the plane.
  static void sweepAxis(const SahBins& bins, int axis, int binCount, uint32_t count,
                        PlaneSplit& best) {
    float rightCost[kMaxBins - 1];
    Box4 rightBounds;
    uint32_t rightCount = 0;
    for (int k = binCount - 1; k >= 1; --k) {
      rightBounds.grow(bins.bounds(axis, k));
      rightCount += bins.size(axis, k);
      rightCost[k - 1] = static_cast<float>(rightCount) * rightBounds.halfArea();
    }
    Box4 leftBounds;
    uint32_t leftCount = 0;
    for (int k = 0; k < binCount - 1; ++k) {
      leftBounds.grow(bins.bounds(axis, k));
      leftCount += bins.size(axis, k);
      if (leftCount == 0 || leftCount == count) continue;
      const float cost = static_cast<float>(leftCount) * leftBounds.halfArea() + rightCost[k];
      if (cost < best.cost) {
        best.cost = cost;
        best.axis = axis;
        best.plane = k;
      }
    }
  }

  // The best plane, the size split when it is much cheaper, or a leaf: when neither separates
  // the primitives, or when the node is cheaper unsplit.
  static SahChoice chooseSplit(const NodeRange& range, const PlaneSplit& plane,
                               const SizeSplitSums& sizes) {
    const uint32_t count = range.count();
    float bestCost = plane.cost;
    bool bySize = false;
    if (sizes.largeCount > 0 && sizes.largeCount < count) {
      const float cost = static_cast<float>(sizes.largeCount) * sizes.large.halfArea() +
                         static_cast<float>(count - sizes.largeCount) * sizes.small.halfArea();
      if (cost < kSizeSplitAdvantage * bestCost) {
        bestCost = cost;
        bySize = true;
      }
    }
    if (plane.axis < 0 && !bySize) return SahChoice::kLeaf;
    if (cheaperAsLeaf(range, bestCost)) return SahChoice::kLeaf;
    return bySize ? SahChoice::kSize : SahChoice::kPlane;
  }

  // Large primitives left, the rest right; the children's bounds are the sums' boxes.
  void splitBySize(const NodeRange& range, const LargeTest& isLarge, const SizeSplitSums& sizes,
                   Split* out) {
    partition(
        range, [&](const BuildPrim& p) { return isLarge(p.lower(), p.upper()); }, out);
    out->left.bounds = sizes.large;
    out->right.bounds = sizes.small;
    out->axis = 0;
  }

  // Splits at `plane`, partitioning by the same binOf that binned, so that the children's bounds
  // can be merged from the bins.
  void splitAtPlane(const NodeRange& range, const BinMapping& map, const SahBins& bins,
                    int binCount, const PlaneSplit& plane, Split* out) {
    const int axis = plane.axis, last = plane.plane;
    partition(
        range, [&](const BuildPrim& p) { return map.binOf(axis, p.lo[axis] + p.hi[axis]) <= last; },
        out);
    Box4 leftBounds, rightBounds;
    for (int k = 0; k < binCount; ++k) {
      (k <= last ? leftBounds : rightBounds).grow(bins.bounds(axis, k));
    }
    out->left.bounds = leftBounds;
    out->right.bounds = rightBounds;
    out->axis = axis;
  }

  // Two primitives: about half of all nodes, nearly all of which become leaves. The only split
  // puts one on each side; binning finds it on the first axis along which the centroids differ
  // (and BinMapping can scale them), at the cost computed below to the bit, so the tree is the
  // same as if they were binned, for less work.
  bool pairSplit(const NodeRange& range, Split* out) {
    int axis = 0;
    while (axis < 3 && BinMapping::scaleFor(range.centroids.extent(axis), 2) == 0.0f) ++axis;
    if (axis == 3) return false;
    Box4 a, b;
    a.grow(prims_[range.begin].lower(), prims_[range.begin].upper());
    b.grow(prims_[range.begin + 1].lower(), prims_[range.begin + 1].upper());
    if (cheaperAsLeaf(range, a.halfArea() + b.halfArea())) return false;

    const uint32_t first = range.begin, second = range.begin + 1;
    if (prims_[second].lo[axis] + prims_[second].hi[axis] <
        prims_[first].lo[axis] + prims_[first].hi[axis]) {
      std::swap(prims_[first], prims_[second]);
      std::swap(a, b);
    }
    out->left = {first, second, a, centroidBounds(first, second)};
    out->right = {second, range.end, b, centroidBounds(second, range.end)};
    out->axis = axis;
    return true;
  }

  // Whether a node that a split of SAH cost `splitCost` (children's count-weighted half areas)
  // would divide is better left a leaf; only nodes that fit one can be.
  static bool cheaperAsLeaf(const NodeRange& range, float splitCost) {
    const float area = range.bounds.halfArea();
    const float relativeCost = kTraversalCost + (area > 0.0f ? splitCost / area : 0.0f);
    return range.count() <= kBvhMaxLeafSize && static_cast<float>(range.count()) <= relativeCost;
  }

  // Partitions `range` in place, primitives for which goesLeft holds first, and sets out's
  // ranges and centroid bounds (not their bounds). Branch-free (Lomuto's scheme with an
  // unconditional swap): which side a primitive goes to is a coin toss for the branch predictor,
  // which a two-pointer partition pays for in mispredictions (docs/performance.md).
  template <typename GoesLeft>
  void partition(const NodeRange& range, const GoesLeft& goesLeft, Split* out) {
    uint32_t mid = range.begin;
    for (uint32_t i = range.begin; i < range.end; ++i) {
      // [begin, mid) went left, [mid, i) right.
      const BuildPrim p = prims_[i];
      const bool left = goesLeft(p);
      prims_[i] = prims_[mid];
      prims_[mid] = p;
      mid += left ? 1u : 0u;
    }
    out->left = {range.begin, mid, Box4(), centroidBounds(range.begin, mid)};
    out->right = {mid, range.end, Box4(), centroidBounds(mid, range.end)};
  }

  Box4 centroidBounds(uint32_t begin, uint32_t end) const {
    Box4 b;
    for (uint32_t i = begin; i < end; ++i) b.grow(prims_[i].centroid2());
    return b;
  }

  // Object median along the widest centroid axis; an arbitrary halving when all centroids
  // coincide. Always yields two non-empty halves for count >= 2.
  void medianSplit(const NodeRange& range, Split* out) {
    const int axis = range.centroids.widestAxis();
    const uint32_t mid = range.begin + range.count() / 2;
    if (range.centroids.extent(axis) > 0.0f) {
      std::nth_element(prims_ + range.begin, prims_ + mid, prims_ + range.end,
                       [axis](const BuildPrim& a, const BuildPrim& b) {
                         return a.lo[axis] + a.hi[axis] < b.lo[axis] + b.hi[axis];
                       });
    }
    out->axis = axis;
    out->left = gather(range.begin, mid);
    out->right = gather(mid, range.end);
  }

  NodeRange gather(uint32_t begin, uint32_t end) const {
    NodeRange r{begin, end, Box4(), Box4()};
    for (uint32_t i = begin; i < end; ++i) {
      const Float4 lo = prims_[i].lower(), hi = prims_[i].upper();
      r.bounds.grow(lo, hi);
      r.centroids.grow(lo + hi);
    }
    return r;
  }

  BuildPrim* const prims_;  // concurrent splits own disjoint ranges
};

// Builds the subtree of `range` into its slots of `nodes`, which start at `base`: a subtree of k
// primitives has at most 2k - 1 nodes, so a split node's left subtree fits in the 2 * left - 1
// slots after it and the right one starts at base + 2 * left. Large subtrees are split in
// parallel, small ones built serially. Every node is written once, in place; slots a subtree
// does not need stay unwritten (never touched, so never paged in) and are unreachable. Indices
// stay below 2^32 for fewer than 2^31 primitives.
BuildStats buildTop(Builder& builder, const NodeRange& range, uint32_t depth, BinaryBvhNode* nodes,
                    uint32_t base) {
  Split s;
  BuildStats stats;
  if (range.count() < kParallelThreshold || !builder.split(range, depth, &s)) {
    uint32_t next = base;
    builder.buildSerial(range, depth, nodes, next, stats);
    return stats;
  }
  const uint32_t rightBase = base + 2 * s.left.count();
  BinaryBvhNode node = makeInterior(range.bounds, s.axis);
  node.offset = rightBase;
  new (&nodes[base]) BinaryBvhNode(node);
  BuildStats right;
  tbb::parallel_invoke([&] { stats = buildTop(builder, s.left, depth + 1, nodes, base + 1); },
                       [&] { right = buildTop(builder, s.right, depth + 1, nodes, rightBase); });
  stats.merge(right);
  return stats;
}

// Raw storage for `count` binary nodes: allocated, not initialised, so that pages no node is
// written to are never touched.
struct RawNodesDeleter {
  void operator()(BinaryBvhNode* p) const { ::operator delete(p); }
};
using RawNodes = std::unique_ptr<BinaryBvhNode[], RawNodesDeleter>;
RawNodes allocateNodes(size_t count) {
  return RawNodes(static_cast<BinaryBvhNode*>(::operator new(count * sizeof(BinaryBvhNode))));
}

struct RootBounds {
  Box4 bounds, centroids;
};

}  // namespace

namespace {

// The build over primCount primitives whose boxes and indices boxOf(p, &index) gives.
template <class BoxOf>
BvhBuildResult buildOver(uint32_t primCount, const BoxOf& boxOf) {
  const auto start = std::chrono::steady_clock::now();
  BvhBuildResult result;
  if (primCount > 0) {
    // 1. Primitive bounds, root bounds and root centroid bounds in one parallel pass.
    // Default-initialised (not zeroed): the pass below writes every element, in parallel.
    std::unique_ptr<BuildPrim[]> prims(new BuildPrim[primCount]);
    const RootBounds root = tbb::parallel_reduce(
        tbb::blocked_range<uint32_t>(0, primCount, 4096), RootBounds(),
        [&](const tbb::blocked_range<uint32_t>& r, RootBounds acc) {
          for (uint32_t p = r.begin(); p < r.end(); ++p) {
            uint32_t index;
            const Bounds3 b = boxOf(p, &index);
            prims[p] = BuildPrim(b, index);
            acc.bounds.grow(prims[p].lower(), prims[p].upper());
            acc.centroids.grow(prims[p].centroid2());
          }
          return acc;
        },
        [](RootBounds a, const RootBounds& b) {
          a.bounds.grow(b.bounds);
          a.centroids.grow(b.centroids);
          return a;
        });

    // 2. The binary tree, in place (see buildTop), then collapsed 4-wide.
    Builder builder(prims.get());
    RawNodes nodes = allocateNodes(2 * size_t(primCount) - 1);
    const BuildStats stats =
        buildTop(builder, {0, primCount, root.bounds, root.centroids}, 0, nodes.get(), 0);
    result.leafCount = stats.leafCount;
    result.maxDepth = stats.maxDepth;

    result.primIndices.resize(primCount);
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, primCount, 1u << 16),
                      [&](const tbb::blocked_range<uint32_t>& r) {
                        for (uint32_t i = r.begin(); i < r.end(); ++i)
                          result.primIndices[i] = prims[i].index;
                      });
    prims.reset();  // release before the wide nodes are allocated
    // Every interior node has two children, so the tree has 2 * leaves - 1 nodes.
    result.wideNodes = collapseToWide(nodes.get(), 2 * result.leafCount - 1);
  }
  result.buildSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

BvhBuildResult buildBvh(const Sphere* spheres, uint32_t sphereCount, const Vec3* positions,
                        const Triangle* triangles, uint32_t triangleCount) {
  return buildOver(sphereCount + triangleCount, [&](uint32_t p, uint32_t* index) {
    *index = p;
    return p < sphereCount ? sphereBounds(spheres[p])
                           : triangleBounds(positions, triangles[p - sphereCount]);
  });
}

BvhBuildResult buildBvhOfBoxes(const Bounds3* boxes, const uint32_t* prims, uint32_t count) {
  return buildOver(count, [&](uint32_t p, uint32_t* index) {
    *index = prims[p];
    return boxes[p];
  });
}

}  // namespace candela
