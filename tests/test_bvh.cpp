// BVH build and traversal: the tree's invariants, and agreement with brute-force intersection of
// every primitive on random scenes and rays.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "geometry/aabb.h"
#include "geometry/bvh_build.h"
#include "geometry/bvh_traverse.h"
#include "geometry/primitive_bounds.h"
#include "test_random.h"
#include "test_geometry_view.h"

namespace candela {
namespace {

using test::randomUnitVector;

constexpr uint32_t kNone = 0xffffffffu;

struct TestScene {
  std::vector<Sphere> spheres;
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;
  BvhBuildResult bvh;

  void build() {
    bvh = buildBvh(spheres.data(), static_cast<uint32_t>(spheres.size()), positions.data(),
                   triangles.data(), static_cast<uint32_t>(triangles.size()));
  }
  uint32_t primitiveCount() const {
    return static_cast<uint32_t>(spheres.size() + triangles.size());
  }
  void addTriangle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const uint32_t i = static_cast<uint32_t>(positions.size());
    positions.insert(positions.end(), {a, b, c});
    triangles.push_back(Triangle{{i, i + 1, i + 2}, 0});
  }
  Bounds3 primitiveBounds(uint32_t p) const {
    if (p < spheres.size()) {
      const Sphere& s = spheres[p];
      return Bounds3(s.center - Vec3(s.radius), s.center + Vec3(s.radius));
    }
    const Triangle& t = triangles[p - spheres.size()];
    Bounds3 b(positions[t.v[0]]);
    b.grow(positions[t.v[1]]);
    b.grow(positions[t.v[2]]);
    return b;
  }
  GeometryView view() const {
    static const std::vector<OctNormal> kNoNormals;
    GeometryView v = test::geometryView(spheres, positions, kNoNormals, triangles);
    v.nodes = bvh.wideNodes.data();
    v.nodeCount = static_cast<uint32_t>(bvh.wideNodes.size());
    v.primIndices = bvh.primIndices.data();
    v.primIndexCount = static_cast<uint32_t>(bvh.primIndices.size());
    return v;
  }
};

float logUniform(std::mt19937& gen, float lo, float hi) {
  std::uniform_real_distribution<float> u(std::log(lo), std::log(hi));
  return std::exp(u(gen));
}

// Triangles and spheres of sizes spanning three decades, random shapes and orientations, in a
// box of half-size 10; one triangle in ten is a sliver.
TestScene randomSoup(uint32_t triangleCount, uint32_t sphereCount, uint32_t seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<float> u(-10.0f, 10.0f);
  TestScene s;
  for (uint32_t i = 0; i < sphereCount; ++i)
    s.spheres.push_back(Sphere{Vec3(u(gen), u(gen), u(gen)), logUniform(gen, 0.01f, 2.0f), 0});
  for (uint32_t i = 0; i < triangleCount; ++i) {
    const Vec3 c(u(gen), u(gen), u(gen));
    const float size = logUniform(gen, 0.01f, 5.0f);
    const Vec3 a = c + size * randomUnitVector(gen), b = c + size * randomUnitVector(gen);
    const Vec3 d = i % 10 == 0 ? a + 0.999f * (b - a) + 1e-3f * size * randomUnitVector(gen)
                               : c + size * randomUnitVector(gen);
    s.addTriangle(a, b, d);
  }
  s.build();
  return s;
}

// Random rays from around the scene: non-unit directions, some with zero components (infinite
// inverse directions in the slab test), some with a finite tMax.
Ray randomRay(std::mt19937& gen, int i) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Ray r;
  r.origin = Vec3(24 * u(gen) - 12, 24 * u(gen) - 12, 24 * u(gen) - 12);
  r.direction = randomUnitVector(gen) * (0.5f + 1.5f * u(gen));
  if (i % 10 == 1) r.direction.x = 0.0f;
  if (i % 20 == 2) r.direction.y = r.direction.z = 0.0f;
  if (i % 5 == 3) r.tMax = 20.0f * u(gen);
  return r;
}

// Checks every structural invariant of the scene's BVH: the 4-wide nodes the renderer traverses.
void expectValidBvh(const TestScene& s) {
  const BvhBuildResult& bvh = s.bvh;
  const std::vector<BvhNode>& nodes = bvh.wideNodes;
  ASSERT_EQ(bvh.primIndices.size(), s.primitiveCount());
  if (s.primitiveCount() == 0) {
    EXPECT_TRUE(nodes.empty());
    return;
  }
  ASSERT_FALSE(nodes.empty());
  std::vector<int> primSeen(s.primitiveCount(), 0);
  uint32_t leaves = 0, expectedNext = 0;
  struct Entry {
    uint32_t node, depth;
    Bounds3 bounds;  // the parent's box for this node
  };
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<Entry> stack = {{0, 0, Bounds3(Vec3(-inf), Vec3(inf))}};
  // A pre-order walk (slots in order) must visit the nodes exactly in index order.
  while (!stack.empty()) {
    const Entry e = stack.back();
    stack.pop_back();
    ASSERT_EQ(e.node, expectedNext++) << "not depth-first";
    EXPECT_LE(e.depth, bvh.maxDepth);
    const BvhNode& w = nodes[e.node];
    int used = 0;
    std::vector<Entry> inner;
    for (int c = 0; c < 4; ++c) {
      if (w.child[c] == kNoBvhChild) {
        EXPECT_EQ(w.count[c], 0);
        continue;
      }
      EXPECT_EQ(used++, c) << "node " << e.node << ": empty slots must come last";
      const Bounds3 box(Vec3(w.lo[0][c], w.lo[1][c], w.lo[2][c]),
                        Vec3(w.hi[0][c], w.hi[1][c], w.hi[2][c]));
      EXPECT_TRUE(e.bounds.contains(box)) << "node " << e.node << " slot " << c;
      if (w.count[c] > 0) {
        ++leaves;
        EXPECT_LE(w.count[c], kBvhMaxLeafSize);
        ASSERT_LE(w.child[c] + w.count[c], bvh.primIndices.size());
        for (uint32_t i = 0; i < w.count[c]; ++i) {
          const uint32_t p = bvh.primIndices[w.child[c] + i];
          ASSERT_LT(p, s.primitiveCount());
          ++primSeen[p];
          EXPECT_TRUE(box.contains(s.primitiveBounds(p))) << "primitive " << p;
        }
      } else {
        ASSERT_GT(w.child[c], e.node);
        ASSERT_LT(w.child[c], nodes.size());
        inner.push_back({w.child[c], e.depth + 1, box});
      }
    }
    EXPECT_GE(used, e.node == 0 ? 1 : 2) << "node " << e.node;
    stack.insert(stack.end(), inner.rbegin(), inner.rend());
  }
  EXPECT_EQ(expectedNext, nodes.size()) << "unreachable nodes";
  for (uint32_t p = 0; p < s.primitiveCount(); ++p) EXPECT_EQ(primSeen[p], 1) << "primitive " << p;
  EXPECT_EQ(leaves, bvh.leafCount);  // every binary leaf is one leaf slot
  EXPECT_LE(bvh.maxDepth, kBvhMaxDepth);
}

// Compares intersectClosest and intersectAny with brute force on `rays` rays; returns the number
// of rays that hit something.
int expectMatchesBruteForce(const TestScene& s, int rays, uint32_t seed,
                            bool primitivesMayTie = false) {
  const GeometryView view = s.view();
  std::mt19937 gen(seed);
  int hits = 0;
  for (int i = 0; i < rays; ++i) {
    const Ray r = randomRay(gen, i);
    Hit bvhHit, bruteHit;
    const bool found = intersectClosest(view, r, &bvhHit);
    const bool bruteFound = intersectClosestBruteForce(view, r, &bruteHit);
    EXPECT_EQ(found, bruteFound) << "ray " << i;
    if (found && bruteFound) {
      ++hits;
      EXPECT_NEAR(bvhHit.t, bruteHit.t, 1e-6f * bruteHit.t) << "ray " << i;
      if (!primitivesMayTie) {
        EXPECT_EQ(bvhHit.prim, bruteHit.prim) << "ray " << i;
        EXPECT_EQ(bvhHit.b1, bruteHit.b1);
        EXPECT_EQ(bvhHit.b2, bruteHit.b2);
      }
    }
    // Any-hit: skip nothing, the nearest primitive, or a random one.
    uint32_t skip = kNone;
    if (i % 3 == 1 && bruteFound) skip = bruteHit.prim;
    if (i % 3 == 2 && s.primitiveCount() > 0)
      skip = static_cast<uint32_t>(gen() % s.primitiveCount());
    EXPECT_EQ(intersectAny(view, r, skip), intersectAnyBruteForce(view, r, skip)) << "ray " << i;
  }
  return hits;
}

TEST(Aabb, SlabTest) {
  const Vec3 lo(-1, -1, -1), hi(1, 2, 3);
  auto hit = [&](const Vec3& o, const Vec3& d, float tMax = kInfinity) {
    return intersectAabb(lo, hi, o, Vec3(1.0f / d.x, 1.0f / d.y, 1.0f / d.z), tMax);
  };
  EXPECT_TRUE(hit(Vec3(0, 0, -5), Vec3(0, 0, 1)));
  EXPECT_FALSE(hit(Vec3(0, 0, -5), Vec3(0, 0, -1)));  // box behind
  EXPECT_FALSE(hit(Vec3(0, 0, -5), Vec3(0, 0, 1), 3.9f));
  EXPECT_TRUE(hit(Vec3(0, 0, -5), Vec3(0, 0, 1), 4.1f));
  EXPECT_TRUE(hit(Vec3(0, 0, 0), Vec3(1, 1, 1)));  // origin inside
  EXPECT_FALSE(hit(Vec3(1.5f, 0, -5), Vec3(0, 0, 1)));
  EXPECT_TRUE(hit(Vec3(-5, -5, -5), Vec3(1, 1, 1)));
  // Parallel to the x slabs with the origin exactly on one: 0 * inf is NaN, and must not matter,
  // for either sign of zero in the direction (a -0 once made the exit distance -inf).
  for (float zero : {0.0f, -0.0f}) {
    EXPECT_TRUE(hit(Vec3(1, 0, -5), Vec3(zero, 0, 1)));
    EXPECT_TRUE(hit(Vec3(-1, 0, -5), Vec3(zero, 0, 1)));
    EXPECT_TRUE(hit(Vec3(-1, 2, -5), Vec3(zero, zero, 1)));
    EXPECT_TRUE(hit(Vec3(1, -1, 3), Vec3(zero, zero, -1)));
    EXPECT_FALSE(hit(Vec3(1.5f, 0, -5), Vec3(zero, 0, 1)));
  }
  // Degenerate (flat) boxes are still hit.
  EXPECT_TRUE(intersectAabb(Vec3(-1, -1, 0), Vec3(1, 1, 0), Vec3(0.5f, 0.5f, 2),
                            Vec3(INFINITY, INFINITY, -1.0f), kInfinity));
}

TEST(Aabb, BoundsOperations) {
  Bounds3 b;
  EXPECT_TRUE(b.empty());
  EXPECT_EQ(b.surfaceArea(), 0.0f);
  b.grow(Vec3(1, 2, 3));
  b.grow(Vec3(-1, 0, 4));
  EXPECT_FALSE(b.empty());
  EXPECT_EQ(b.extent().x, 2.0f);
  EXPECT_EQ(b.extent().y, 2.0f);
  EXPECT_EQ(b.extent().z, 1.0f);
  EXPECT_EQ(b.surfaceArea(), 2.0f * (4 + 2 + 2));
  EXPECT_EQ(b.centroid().z, 3.5f);
  const Bounds3 u = unionBounds(b, Bounds3(Vec3(5, 5, 5)));
  EXPECT_EQ(u.hi.x, 5.0f);
  EXPECT_TRUE(u.contains(b));
  EXPECT_FALSE(b.contains(u));
}

// Rays with a NaN or infinite origin or direction hit nothing (regression: their NaN slab tests
// counted every slot of a node as hit, empty slots included, and traversal followed an empty
// slot's child 0xffffffff out of the node array).
TEST(Bvh, NonFiniteRaysHitNothing) {
  const TestScene s = randomSoup(6, 1, 5);  // 7 primitives: the root has empty slots
  const GeometryView view = s.view();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const Vec3 bad[] = {Vec3(nan, 0, 1), Vec3(0, inf, 0), Vec3(-inf, nan, 0)};
  for (const Vec3& v : bad) {
    for (bool originBad : {false, true}) {
      Ray r;
      r.origin = originBad ? v : Vec3(0.1f, 0.2f, -30.0f);
      r.direction = originBad ? Vec3(0, 0, 1) : v;
      Hit hit;
      EXPECT_FALSE(intersectClosest(view, r, &hit));
      EXPECT_FALSE(intersectAny(view, r, 0xffffffffu));
    }
  }
}

TEST(Bvh, MatchesBruteForceOnRandomSoup) {
  const TestScene s = randomSoup(2000, 200, 1);
  expectValidBvh(s);
  EXPECT_GT(expectMatchesBruteForce(s, 10000, 2), 3000);
}

TEST(Bvh, TrianglesOnlyAndSpheresOnly) {
  const TestScene triangles = randomSoup(1500, 0, 3);
  expectValidBvh(triangles);
  expectMatchesBruteForce(triangles, 3000, 4);
  const TestScene spheres = randomSoup(0, 500, 5);
  expectValidBvh(spheres);
  expectMatchesBruteForce(spheres, 3000, 6);
}

TEST(Bvh, EmptySceneHasNoNodesAndMissesEverything) {
  TestScene s;
  s.build();
  EXPECT_TRUE(s.bvh.wideNodes.empty());
  EXPECT_EQ(s.bvh.leafCount, 0u);
  expectValidBvh(s);
  std::mt19937 gen(7);
  for (int i = 0; i < 100; ++i) {
    const Ray r = randomRay(gen, i);
    Hit hit;
    EXPECT_FALSE(intersectClosest(s.view(), r, &hit));
    EXPECT_FALSE(hit.valid());
    EXPECT_FALSE(intersectAny(s.view(), r, kNone));
  }
}

TEST(Bvh, SinglePrimitive) {
  TestScene sphere;
  sphere.spheres.push_back(Sphere{Vec3(0, 0, 5), 1.0f, 0});
  sphere.build();
  TestScene triangle;
  triangle.addTriangle(Vec3(-1, -1, 5), Vec3(1, -1, 5), Vec3(0, 1, 5));
  triangle.build();
  for (const TestScene* s : {&sphere, &triangle}) {
    expectValidBvh(*s);
    EXPECT_EQ(s->bvh.wideNodes.size(), 1u);
    EXPECT_EQ(s->bvh.leafCount, 1u);
    EXPECT_EQ(s->bvh.maxDepth, 0u);
    Ray r;
    r.direction = Vec3(0, 0, 1);
    Hit hit;
    ASSERT_TRUE(intersectClosest(s->view(), r, &hit));
    EXPECT_EQ(hit.prim, 0u);
    EXPECT_NEAR(hit.t, s == &sphere ? 4.0f : 5.0f, 1e-6f);
    EXPECT_TRUE(intersectAny(s->view(), r, kNone));
    EXPECT_FALSE(intersectAny(s->view(), r, 0));  // the only blocker is skipped
    r.direction = Vec3(0, 0, -1);
    EXPECT_FALSE(intersectClosest(s->view(), r, &hit));
    expectMatchesBruteForce(*s, 500, 8);
  }
}

TEST(Bvh, CoincidentCentroidsStillSplitIntoSmallLeaves) {
  TestScene s;
  for (int i = 0; i < 200; ++i) s.addTriangle(Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(0, 2, 0));
  for (int i = 0; i < 50; ++i) s.spheres.push_back(Sphere{Vec3(0, 0, 0), 0.1f * (i + 1), 0});
  s.build();
  expectValidBvh(s);
  // Identical triangles tie exactly, so only the distance is compared.
  expectMatchesBruteForce(s, 2000, 9, /*primitivesMayTie=*/true);
}

TEST(Bvh, RoomWallsAreSetApartFromTheSmallContents) {
  // The default scene's shape: six huge wall spheres around a small triangle mesh. Centroid
  // planes alone spread the mesh over several room-sized boxes; the size split must give the
  // mesh and the small spheres one subtree of their own, whose box is theirs alone.
  TestScene s;
  const float wall = 1000.0f, radius = 940.0f;
  for (int axis = 0; axis < 3; ++axis) {
    for (float side : {-1.0f, 1.0f}) {
      Vec3 c(0.0f);
      c[axis] = side * wall;
      s.spheres.push_back(Sphere{c, radius, 0});
    }
  }
  s.spheres.push_back(Sphere{Vec3(-10, 0, -25), 10.0f, 0});
  std::mt19937 gen(21);
  std::uniform_real_distribution<float> u(-5.0f, 5.0f);
  Bounds3 contents = sphereBounds(s.spheres.back());
  for (int i = 0; i < 400; ++i) {
    const Vec3 a(10 + u(gen), u(gen), u(gen));
    const Vec3 b = a + Vec3(0.3f * u(gen), 0.3f * u(gen), 0.3f * u(gen));
    const Vec3 c = a + Vec3(0.3f * u(gen), 0.3f * u(gen), 0.3f * u(gen));
    s.addTriangle(a, b, c);
    for (const Vec3& p : {a, b, c}) contents.grow(p);
  }
  s.build();
  expectValidBvh(s);
  expectMatchesBruteForce(s, 3000, 22);

  // Count the primitives below every slot of the wide nodes; one slot must hold exactly the 401
  // small primitives, within the contents' box.
  const std::vector<BvhNode>& nodes = s.bvh.wideNodes;
  std::vector<uint32_t> below(nodes.size(), 0);  // per wide node, over its slots
  bool found = false;
  for (size_t i = nodes.size(); i-- > 0;) {  // children have larger indices than their parents
    for (int c = 0; c < 4; ++c) {
      if (nodes[i].child[c] == kNoBvhChild) continue;
      const uint32_t n = nodes[i].count[c] > 0 ? nodes[i].count[c] : below[nodes[i].child[c]];
      below[i] += n;
      if (n != 401) continue;
      found = true;
      const BvhNode& w = nodes[i];
      EXPECT_TRUE(contents.contains(Bounds3(Vec3(w.lo[0][c], w.lo[1][c], w.lo[2][c]),
                                            Vec3(w.hi[0][c], w.hi[1][c], w.hi[2][c]))));
    }
  }
  EXPECT_TRUE(found) << "the walls are mixed into the small primitives' subtrees";
}

TEST(Bvh, PathologicalScaleSpreadKeepsTheDepthBounded) {
  // Clusters of spheres at power-of-two distances along the six half-axes, over the whole float
  // range: the binned SAH can only peel a few clusters off per level, and left alone builds a
  // tree over 100 levels deep. The build must stay within the traversal stack's bound.
  TestScene s;
  for (int axis = 0; axis < 3; ++axis)
    for (int k = -120; k <= 120; ++k)
      for (int j = 0; j < 3; ++j)
        for (float sign : {-1.0f, 1.0f}) {
          Vec3 c(0.0f);
          c[axis] = sign * std::ldexp(1.0f + 0.25f * j, k);
          s.spheres.push_back(Sphere{c, std::ldexp(0.1f, k), 0});
        }
  s.build();
  expectValidBvh(s);
  EXPECT_LE(s.bvh.maxDepth, kBvhMaxDepth);
  // Rays aimed at random spheres from a few radii away, at scales whose squares are still normal
  // floats (intersection itself needs that).
  std::mt19937 gen(10);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const GeometryView view = s.view();
  for (int i = 0; i < 2000; ++i) {
    const Sphere& target = s.spheres[gen() % s.spheres.size()];
    if (target.radius < 1e-12f || target.radius > 1e12f) continue;
    Ray r;
    r.origin = target.center + target.radius * 4.0f * randomUnitVector(gen);
    r.direction = target.center + target.radius * Vec3(u(gen), u(gen), u(gen)) - r.origin;
    Hit bvhHit, bruteHit;
    const bool found = intersectClosest(view, r, &bvhHit);
    ASSERT_EQ(found, intersectClosestBruteForce(view, r, &bruteHit)) << "ray " << i;
    if (found) {
      EXPECT_EQ(bvhHit.prim, bruteHit.prim) << "ray " << i;
      EXPECT_EQ(bvhHit.t, bruteHit.t) << "ray " << i;
    }
  }
}

TEST(Bvh, LargeSceneBuildsTheSameTreeOnAnyThreadCount) {
  // Above the parallel threshold, so the parallel top and its in-place node slots are exercised.
  const TestScene parallel = randomSoup(100000, 1000, 11);
  expectValidBvh(parallel);
  TestScene serial = parallel;
  {
    tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
    serial.build();
  }
  ASSERT_EQ(serial.bvh.wideNodes.size(), parallel.bvh.wideNodes.size());
  EXPECT_EQ(std::memcmp(serial.bvh.wideNodes.data(), parallel.bvh.wideNodes.data(),
                        parallel.bvh.wideNodes.size() * sizeof(BvhNode)),
            0);
  EXPECT_EQ(serial.bvh.primIndices, parallel.bvh.primIndices);
  expectMatchesBruteForce(parallel, 300, 12);
}

}  // namespace
}  // namespace candela
